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

// A body whose pitch has no inertia, on two unequal springs, over joints (two harmonics,
// which load the massless pitch too): started on the steady motion, bounce and the statically
// recovered pitch follow the harmonic response, displacement and velocity. The error is the
// first-order hold's O(Δt²): its sampling error starts an undamped free bounce at
// ω_n ≈ 40 rad/s, which shows most in the velocity (2.5e-5 of the amplitude at Δt = 1 ms,
// 1e-6 at 0.2 ms). 1e-5 of the amplitude leaves that room and would catch a wrong sign or
// a missing load term (errors of order 1).
TEST(LinearSimulation, MasslessPitchFollowsStatically) {
  const LinearSystem sys = assemble(load_vehicle(write_temp("massless_pitch.toml", R"toml(
[vehicle]
name = "massless pitch"
[[body]]
name = "m"
mass = "1000 kg"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "yaw"]
[[element]]
name = "front"
upper = "m"
point = ["1 m", "0 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
[[element]]
name = "rear"
upper = "m"
point = ["-1.5 m", "0 m", "0 m"]
vertical = { stiffness = "0.6 MN/m" }
)toml")),
                                     DofSet::vertical);
  const int bounce = sys.index_of("m.bounce"), pitch = sys.index_of("m.pitch");
  ASSERT_GE(bounce, 0);
  ASSERT_GE(pitch, 0);
  ASSERT_EQ(sys.mass(pitch, pitch), 0.0);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.01;
  j.dip_length = 2.0;  // a short dip: the whole-rail cosine has no second harmonic
  j.harmonics = 2;
  const auto source = make_source(j);
  const double V = 8.0;
  std::vector<std::pair<double, Eigen::VectorXcd>> steady;  // (ω, X) per harmonic
  for (int k = 1; k <= 2; ++k) {
    const HarmonicLoad load = source->load(sys, V, k);
    const Eigen::VectorXcd Q = generalized_load(sys, load);
    ASSERT_GT(std::abs(Q(pitch)), 0.0);
    steady.push_back({2 * kPi * load.frequency_hz,
                      harmonic_response(sys, modes, Q, load.frequency_hz).displacement});
  }
  auto at = [&](double t, int dof, bool velocity) {
    double sum = 0.0;
    for (const auto& [w, X] : steady) {
      const std::complex<double> e = std::exp(std::complex<double>(0.0, w * t));
      sum += (velocity ? std::complex<double>(0.0, w) * X(dof) * e : X(dof) * e).real();
    }
    return sum;
  };
  SimulationOptions o;
  o.speed = V;
  o.duration = 3.0;
  o.time_step = 2e-4;
  o.initial = {{"m.bounce", at(0.0, bounce, false), at(0.0, bounce, true)}};
  const TimeHistory h = simulate_linear(sys, {source.get()}, o);
  for (int dof : {bounce, pitch})
    for (bool velocity : {false, true}) {
      double worst = 0.0, amplitude = 0.0;
      for (int i = 0; i < h.time.size(); ++i) {
        const double exact = at(h.time(i), dof, velocity);
        const double simulated = velocity ? h.velocity(i, dof) : h.displacement(i, dof);
        worst = std::max(worst, std::abs(simulated - exact));
        amplitude = std::max(amplitude, std::abs(exact));
      }
      EXPECT_LT(worst, 1e-5 * amplitude) << sys.dofs[dof].label << (velocity ? " velocity" : " displacement");
    }
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
