// The C++ side of python_overhead.py: the calls the Python package makes, timed in C++ on the
// same inputs, so that the script can state what a call costs on top of the library.
//
//   python_call_timing DATA_DIR REPEATS   prints "<call> <seconds per call>" per line: the
//                                         median over 5 batches of REPEATS calls each
#include <algorithm>
#include <chrono>
#include <complex>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "railmodal/railmodal.hpp"

using namespace railmodal;

namespace {

// Seconds per call: the median over 5 batches of `repeats` calls (the machine is shared).
double per_call(int repeats, const std::function<void()>& call) {
  std::vector<double> batches;
  for (int b = 0; b < 5; ++b) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < repeats; ++i) call();
    batches.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats);
  }
  std::nth_element(batches.begin(), batches.begin() + 2, batches.end());
  return batches[2];
}

// What the binding's frf() does: one direct solve per frequency, the outputs kept.
std::vector<std::complex<double>> frf(const LinearSystem& system, const ModalResult& modes, int input,
                                      const std::vector<double>& frequencies) {
  Eigen::VectorXcd load = Eigen::VectorXcd::Zero(system.size());
  load[input] = 1.0;
  std::vector<std::complex<double>> values(frequencies.size() * static_cast<std::size_t>(system.size()));
  for (std::size_t f = 0; f < frequencies.size(); ++f) {
    const HarmonicResponse r = harmonic_response(system, modes, load, frequencies[f]);
    for (int o = 0; o < system.size(); ++o) {
      const bool unbounded = r.unbounded && unbounded_at(r, modes, o);
      values[f * static_cast<std::size_t>(system.size()) + static_cast<std::size_t>(o)] =
          unbounded ? 0.0 : r.displacement[o];
    }
  }
  return values;
}

volatile double sink = 0.0;  // keeps the results alive so no call is optimised away

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: python_call_timing DATA_DIR REPEATS\n";
    return 2;
  }
  const std::string data = argv[1];
  const int repeats = std::max(1, std::atoi(argv[2]));
  const Vehicle car = load_vehicle(data + "/vehicles/resort_car.toml");
  const LinearSystem system = assemble(car, DofSet::all);
  const ModalResult modes = solve_modes(system);
  SparseSystem one;
  one.dofs.resize(1);
  one.dofs[0].label = "dof1";
  one.dofs[0].body = -1;
  one.mass = Eigen::MatrixXd::Identity(1, 1).sparseView();
  one.stiffness = (4.0 * Eigen::MatrixXd::Identity(1, 1)).sparseView();
  one.damping = Eigen::SparseMatrix<double>(1, 1);
  const LinearSystem single = to_linear_system(one);
  std::vector<double> frequencies(1000);
  for (std::size_t i = 0; i < frequencies.size(); ++i) frequencies[i] = 0.01 * static_cast<double>(i + 1);
  const Scene scene = load_scene(data + "/scenes/resort_car_10m_rails.toml");
  std::vector<double> speeds(10000);
  for (std::size_t i = 0; i < speeds.size(); ++i) speeds[i] = 1.0 + 0.004 * static_cast<double>(i);
  OutputRequest bounce;
  bounce.dof = system.index_of("body.bounce");
  const int input = system.index_of("body.bounce");

  std::cout << "modes_1dof " << per_call(repeats * 20, [&] { sink = sink + solve_modes(single).modes[0].eigenvalue; }) << "\n";
  std::cout << "assemble " << per_call(repeats, [&] { sink = sink + assemble(car, DofSet::all).mass(0, 0); }) << "\n";
  std::cout << "modes " << per_call(repeats, [&] { sink = sink + solve_modes(system).modes[0].eigenvalue; }) << "\n";
  std::cout << "frf_1000 " << per_call(std::max(1, repeats / 50), [&] {
    sink = sink + frf(system, modes, input, frequencies)[0].real();
  }) << "\n";
  std::cout << "amplitude_curve_10000 " << per_call(std::max(1, repeats / 20), [&] {
    sink = sink + amplitude_curves(system, modes, *scene.sources[0], 0, {bounce}, SpeedGrid(speeds))[0].amplitudes[0];
  }) << "\n";
  std::cout << "study_critical_speeds " << per_call(std::max(1, repeats / 20), [&] {
    sink = sink + study_critical_speeds(scene, car).critical_speeds.size();
  }) << "\n";
  return 0;
}
