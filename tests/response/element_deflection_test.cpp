// Dynamic deflection of suspension elements (element_deflection_curves): the stretch a spring
// sees, body motion at its point minus the track under it, and leaf friction linearised at
// a chosen stretch (docs/studies.md, "Permissible dynamic deflections").
#include <cmath>
#include <complex>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::unique_ptr<ExcitationSource> joints(double dip_depth) {
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = dip_depth;
  return make_source(j);
}

struct BounceOnly {
  LinearSystem system;
  ModalResult modes;
  BounceOnly() {
    // Example 3's wagon reduced to its bounce (two-axle digest §2.6): one DOF on two leaf springs.
    system = assemble(load_vehicle(data_file("two_axle_example3_bounce_only.toml")), DofSet::vertical);
    modes = solve_modes(system);
  }
};

// Below resonance and without damping the body follows x = Σ kᵢuᵢ/(Σ kᵢ − mω²) (the book's
// off-resonance form (172)), and the leading spring stretches x − u_leading: written out
// here from the wheel inputs the source gives, against the general path. Both are a handful
// of floating-point operations on the same inputs: 1e-12.
TEST(ElementDeflection, OneDofWagonStretchIsBodyMinusTrack) {
  const BounceOnly w;
  const auto source = joints(0.005);
  ASSERT_EQ(w.system.size(), 1);
  for (double speed : {8.0, 12.0, 30.0}) {
    const HarmonicLoad load = source->load(w.system, speed, 1);
    const double omega = 2.0 * kPi * load.frequency_hz;
    std::complex<double> u[2] = {0.0, 0.0}, force = 0.0;
    double k_sum = 0.0;
    for (int e = 0; e < 2; ++e) {
      const double k = series_stiffness(w.system.vehicle.elements[e].vertical_stages);
      k_sum += k;
      for (const WheelInput& in : load.wheels)
        if (w.system.track_inputs[in.track_input].element == e)
          u[e] += in.amplitude(2) * std::exp(std::complex<double>(0.0, -omega * in.delay_s));
      force += k * u[e];
    }
    const std::complex<double> x = force / (k_sum - omega * omega * w.system.mass(0, 0));
    const auto curves = element_deflection_curves(w.system, w.modes, *source, 0, {0, 1}, {speed});
    ASSERT_EQ(curves.size(), 2u);
    for (int e = 0; e < 2; ++e) {
      EXPECT_FALSE(curves[e].unbounded[0]);
      EXPECT_NEAR(curves[e].amplitudes[0], std::abs(x - u[e]), 1e-12 * std::abs(x - u[e])) << speed << " " << e;
    }
  }
}

// The force through the springs: |(k + iωc)·y| with c = 4R/(πωX) the linearised friction of
// the one leaf stage (share 1), R = φ·P (springs digest §2.3): written out from the element's
// data. Off resonance, where both are plain products: 1e-12.
TEST(ElementDeflection, SpringForceCarriesTheLinearisedFriction) {
  const BounceOnly w;
  const auto source = joints(0.005);
  const double x = 0.02, speed = 12.0;
  const auto curve = element_deflection_curves(w.system, w.modes, *source, 0, {0}, {speed}, {x, x}).front();
  const Element& e = w.system.vehicle.elements[0];
  const double k = series_stiffness(e.vertical_stages);
  const double omega = 2.0 * kPi * source->frequency_hz(speed, 1);
  const double c = 4.0 * e.vertical_stages[0].relative_friction * w.system.element_loads[0] / (kPi * omega * x);
  const double expected = std::abs(std::complex<double>(k, omega * c)) * curve.amplitudes[0];
  EXPECT_NEAR(curve.spring_forces[0], expected, 1e-12 * expected);
  // Without friction the force is the spring's alone.
  const auto plain = element_deflection_curves(w.system, w.modes, *source, 0, {0}, {speed}).front();
  EXPECT_NEAR(plain.spring_forces[0], k * plain.amplitudes[0], 1e-12 * k * plain.amplitudes[0]);
}

TEST(ElementDeflection, UndampedResonanceIsUnboundedNotInfinite) {
  const BounceOnly w;
  const auto source = joints(0.005);
  CriticalSpeedOptions options;
  options.min_speed = 5.0;
  options.max_speed = 60.0;
  const auto critical = find_critical_speeds(w.system, w.modes, {source.get()}, options);
  ASSERT_FALSE(critical.empty());
  // Friction left out (no reference stretch): the bounce resonance has no steady state.
  const auto curves = element_deflection_curves(w.system, w.modes, *source, 0, {0}, {critical.front().speed});
  EXPECT_TRUE(curves[0].unbounded[0]);
  EXPECT_EQ(curves[0].amplitudes[0], 0.0);
}

// Friction linearised at the stretch X, at the bounce resonance (ω² = K/m) of the one-DOF
// wagon: with c = 4R/(πωX) across each of the two springs, (iω·2c)x = Σ(k + iωc)uᵢ, so the
// leading spring stretches y_f = x − u_f = Σkuᵢ/(2iωc) + (u_r − u_f)/2. With u_r = u_f e^{−iψ}
// (equal dips, the trailing wheel later by ψ): Σuᵢ = 2u_f cos(ψ/2) e^{−iψ/2} and
// u_r − u_f = −2i u_f sin(ψ/2) e^{−iψ/2}, so y_f = −i u_f e^{−iψ/2}[k cos(ψ/2)/(ωc) + sin(ψ/2)].
// With s = 4W/(πF₀) the friction threshold scale of the critical-speed criterion (W = 2R,
// F₀ = 2k|u_f||cos(ψ/2)|), k|u_f||cos(ψ/2)|/(ωc) = X/s, hence
//   |y_f| = |X/s + σd|,  |y_r| = |X/s − σd|,  d = |u_r − u_f|/2,  σ = sign(sin ψ):
// the linearised response and the book's (169a) criterion are one energy balance, apart from
// the track's own motion under the springs. A handful of operations on the same inputs: 1e-9.
TEST(ElementDeflection, FrictionLinearisedAtXIsTheResonanceCriterionPlusTheTrackMotion) {
  const BounceOnly w;
  for (double dip : {0.005, 0.020, 0.040}) {
    const auto source = joints(dip);
    CriticalSpeedOptions options;
    options.min_speed = 5.0;
    options.max_speed = 60.0;
    const auto critical = find_critical_speeds(w.system, w.modes, {source.get()}, options);
    ASSERT_FALSE(critical.empty());
    const CriticalSpeed& c = critical.front();
    ASSERT_GT(c.friction_threshold_scale, 0.0);
    const HarmonicLoad load = source->load(w.system, c.speed, 1);
    const double omega = 2.0 * kPi * load.frequency_hz;
    std::complex<double> u[2] = {0.0, 0.0};
    for (const WheelInput& in : load.wheels)
      u[w.system.track_inputs[in.track_input].element] +=
          in.amplitude(2) * std::exp(std::complex<double>(0.0, -omega * in.delay_s));
    ASSERT_NEAR(std::abs(u[0]), std::abs(u[1]), 1e-15 * std::abs(u[0]));  // equal dips
    const double d = std::abs(u[1] - u[0]) / 2.0;
    const double sigma = std::sin(std::arg(u[0] / u[1])) >= 0.0 ? 1.0 : -1.0;
    for (double x : {0.010, 0.030}) {
      const auto curves = element_deflection_curves(w.system, w.modes, *source, 0, {0, 1}, {c.speed}, {x, x});
      const double body = x / c.friction_threshold_scale;
      EXPECT_NEAR(curves[0].amplitudes[0], std::abs(body + sigma * d), 1e-9 * curves[0].amplitudes[0])
          << "leading spring, dip " << dip << ", X " << x;
      EXPECT_NEAR(curves[1].amplitudes[0], std::abs(body - sigma * d), 1e-9 * curves[1].amplitudes[0])
          << "trailing spring, dip " << dip << ", X " << x;
    }
  }
}

}  // namespace
}  // namespace railmodal::test
