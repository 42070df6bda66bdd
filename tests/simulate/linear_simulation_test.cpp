// The linear path: exact free motion, second-order convergence under forcing, massless DOFs.
#include <cmath>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

// m = 1000 kg on k = 1 MN/m with a damper c (ζ = c/(2√(km))).
std::string sdof(double damping) {
  return write_temp("sdof.toml", R"toml(
[vehicle]
name = "sdof"
[[body]]
name = "m"
mass = "1000 kg"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
upper = "m"
point = ["0 m", "0 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
vertical_damping = ")toml" + std::to_string(damping) + R"toml( N*s/m"
)toml");
}

// Free decay from x0: x = x0 e^{−ζωt}(cos ω_d t + ζω/ω_d sin ω_d t). The state transition is
// exact for free motion: agreement to round-off (1e-12 of x0) over 2000 steps.
TEST(LinearSimulation, FreeDecayIsExact) {
  const LinearSystem sys = assemble(load_vehicle(sdof(3000.0)), DofSet::vertical);
  SimulationOptions o;
  o.duration = 2.0;
  o.time_step = 1e-3;
  o.initial = {{"m.bounce", 0.02, 0.0}};
  const TimeHistory h = simulate_linear(sys, {}, o);
  const double w = std::sqrt(1000.0), zeta = 3000.0 / (2 * std::sqrt(1e6 * 1000.0)), wd = w * std::sqrt(1 - zeta * zeta);
  double worst = 0.0;
  for (int i = 0; i < h.time.size(); ++i) {
    const double t = h.time(i);
    const double x = 0.02 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
    worst = std::max(worst, std::abs(h.displacement(i, 0) - x));
  }
  EXPECT_LT(worst, 1e-12 * 0.02);
}

// Forced by whole-rail joint dips through spring and damper: after the transient has died
// away the motion is the steady harmonic response. The first-order hold samples the load, so
// the error falls as Δt²: halving the step divides it by about 4.
TEST(LinearSimulation, ForcedResponseConvergesAtSecondOrder) {
  const LinearSystem sys = assemble(load_vehicle(sdof(20000.0)), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.01;
  const auto source = make_source(j);
  const double V = 8.0;
  const HarmonicLoad load = source->load(sys, V, 1);
  const auto steady = harmonic_response(sys, modes, generalized_load(sys, load), load.frequency_hz);
  const double w = 2 * kPi * load.frequency_hz;
  auto error = [&](double step) {
    SimulationOptions o;
    o.speed = V;
    o.duration = 6.0;  // ζ = 0.32: the transient is e^{−10 t}, gone to 1e-26
    o.time_step = step;
    // Start on the steady motion, so no transient at all.
    o.initial = {{"m.bounce", steady.displacement(0).real(), -w * steady.displacement(0).imag()}};
    const TimeHistory h = simulate_linear(sys, {source.get()}, o);
    double worst = 0.0;
    for (int i = 0; i < h.time.size(); ++i) {
      const double x = (steady.displacement(0) * std::exp(std::complex<double>(0.0, w * h.time(i)))).real();
      worst = std::max(worst, std::abs(h.displacement(i, 0) - x));
    }
    return worst / std::abs(steady.displacement(0));
  };
  const double coarse = error(0.01), fine = error(0.005);
  EXPECT_LT(coarse, 1e-2);
  EXPECT_NEAR(coarse / fine, 4.0, 0.4);
}

// The resort car released from a bounce of its body: energy is conserved without damping
// (the book's cars have none in C), to 1e-9 over 5 s — the transition is exact.
TEST(LinearSimulation, UndampedCarConservesEnergy) {
  const LinearSystem sys = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::vertical);
  SimulationOptions o;
  o.duration = 5.0;
  o.time_step = 2e-3;
  o.initial = {{"body.bounce", 0.02, 0.0}};
  const TimeHistory h = simulate_linear(sys, {}, o);
  auto energy = [&](int i) {
    const Eigen::VectorXd x = h.displacement.row(i).transpose(), v = h.velocity.row(i).transpose();
    return 0.5 * v.dot(sys.mass * v) + 0.5 * x.dot(sys.stiffness * x);
  };
  const double e0 = energy(0);
  for (int i = 0; i < h.time.size(); i += 100) EXPECT_NEAR(energy(i) / e0, 1.0, 1e-9);
}

TEST(LinearSimulation, RejectsBadOptions) {
  const LinearSystem sys = assemble(load_vehicle(sdof(0.0)), DofSet::vertical);
  SimulationOptions o;
  o.duration = 1.0;
  o.time_step = 0.0;
  EXPECT_THROW(simulate_linear(sys, {}, o), std::invalid_argument);
  o.time_step = 1e-3;
  o.initial = {{"m.pitch", 0.1, 0.0}};
  EXPECT_THROW(simulate_linear(sys, {}, o), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal::test
