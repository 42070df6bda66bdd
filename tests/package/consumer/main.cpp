// The README's library example: load a vehicle, assemble, solve, print the modes.
#include <railmodal/railmodal.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: consumer VEHICLE.toml\n";
    return 2;
  }
  try {
    const railmodal::Vehicle vehicle = railmodal::load_vehicle(argv[1]);
    const railmodal::LinearSystem system = railmodal::assemble(vehicle, railmodal::DofSet::all);
    const railmodal::ModalResult result = railmodal::solve_modes(system);
    for (const railmodal::Mode& mode : result.modes)
      std::cout << mode.index << "  " << mode.name << "  " << mode.frequency_hz << " Hz  "
                << mode.period_s << " s\n";
  } catch (const railmodal::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  } catch (const railmodal::NumericalError& e) {
    std::cerr << "numerical failure: " << e.what() << "\n";
    return 4;
  }
}
