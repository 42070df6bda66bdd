// Hunting results built by hand for the report tests: every verdict and open interval the
// report must say, without the solver.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "railmodal/hunting.hpp"

namespace railmodal::test {

// A branch whose damped frequency and damping ratio are the given functions of speed (m/s):
// λ = ωn(−ζ + i√(1 − ζ²)), so that Im λ/2π is the frequency and −Re λ/|λ| the ratio.
inline HuntingBranch hand_branch(const std::string& name, const std::vector<double>& speeds,
                                 const std::function<double(double)>& frequency,
                                 const std::function<double(double)>& zeta) {
  HuntingBranch b;
  b.name = name;
  for (double v : speeds) {
    const double z = zeta(v), f = frequency(v);
    const double wd = 2.0 * M_PI * f, wn = wd / std::sqrt(1.0 - z * z);
    b.eigenvalues.push_back({-z * wn, wd});
    b.damping_ratio.push_back(z);
    b.frequency_hz.push_back(f);
    b.continuity.push_back(1.0);
  }
  return b;
}

inline ResolvedContact hand_contact(const std::string& body, double conicity) {
  ResolvedContact c;
  c.body = body;
  c.axle_load = 100e3;
  c.conicity = conicity;
  c.contact_angle_parameter = 0.0;
  c.roll_parameter = 0.0;
  c.rolling_radius = 0.46;
  c.contact_half_spacing = 0.75;
  c.creep = {9.43e6, 8.46e6, 1.2e4, 1.0e2};
  c.klingel_wavelength =
      conicity > 0.0 ? 2.0 * M_PI * std::sqrt(0.46 * 0.75 / conicity) : std::numeric_limits<double>::infinity();
  return c;
}

// 10 to 500 km/h in 50 speeds, with a wheelset-hunting branch whose ζ is `hunting_zeta` and a
// body branch damped at 10 % throughout.
inline HuntingResult hand_result(const std::function<double(double)>& hunting_zeta) {
  HuntingResult r;
  for (int i = 0; i < 50; ++i) r.speeds.push_back((10.0 + 490.0 * i / 49.0) / 3.6);
  r.dofs = {"wheelset1.lateral", "wheelset1.yaw"};
  r.branches.push_back(hand_branch(
      "wheelset 1 hunting (kinematic)", r.speeds, [](double v) { return v / 20.0; }, hunting_zeta));
  r.branches.push_back(hand_branch(
      "body lateral", r.speeds, [](double) { return 0.8; }, [](double) { return 0.1; }));
  r.contacts.push_back(hand_contact("wheelset1", 0.2));
  return r;
}

// Stable from 10 to 500 km/h.
inline HuntingResult stable_result() {
  HuntingResult r = hand_result([](double v) { return 0.02 + 0.001 * v; });
  r.verdict = HuntingVerdict::stable_throughout;
  return r;
}

// Critical at 200 km/h, restabilised at 300, unstable again from 400 km/h to the end; a
// threshold of 5 % reached at 150 km/h.
inline HuntingResult two_interval_result() {
  auto zeta = [](double v) {
    const double kmh = v * 3.6;
    if (kmh < 200.0) return 0.1 * (200.0 - kmh) / 190.0;
    if (kmh < 300.0) return -0.02;
    if (kmh < 400.0) return 0.03;
    return -0.04;
  };
  HuntingResult r = hand_result(zeta);
  r.verdict = HuntingVerdict::critical_speed_in_range;
  HuntingCriticalSpeed c;
  c.speed = 200.0 / 3.6;
  c.branch = "wheelset 1 hunting (kinematic)";
  c.frequency_hz = 2.778;
  c.klingel_frequency_hz = 2.5;
  c.evaluations = 31;
  r.critical = c;
  UnstableInterval first{200.0 / 3.6, 300.0 / 3.6, false, false, c.branch};
  UnstableInterval second{400.0 / 3.6, 500.0 / 3.6, false, true, c.branch};
  r.unstable_intervals = {first, second};
  r.damping_threshold = 0.05;
  r.threshold_speed = 150.0 / 3.6;
  r.threshold_branch = c.branch;
  return r;
}

// The two-interval result asked about ζ = 12 %: the body branch (10 % throughout) is below it
// from the lowest speed and does not decide it; the hunting branch falls to it at 82.2 km/h.
inline HuntingResult threshold_below_at_lowest_result() {
  HuntingResult r = two_interval_result();
  r.damping_threshold = 0.12;
  r.threshold_speed = 82.2 / 3.6;
  r.threshold_branch = "wheelset 1 hunting (kinematic)";
  r.below_threshold_at_lowest_speed = {"body lateral"};
  return r;
}

// Unstable at 10 km/h, stable from 120 km/h on.
inline HuntingResult unstable_at_lowest_result() {
  HuntingResult r = hand_result([](double v) { return v * 3.6 < 120.0 ? -0.01 : 0.02; });
  r.verdict = HuntingVerdict::unstable_at_lowest_speed;
  r.unstable_intervals = {{10.0 / 3.6, 120.0 / 3.6, true, false, "wheelset 1 hunting (kinematic)"}};
  return r;
}

// The two-interval result with a design curve over four conicities: one stable throughout,
// two with a critical speed, one unstable at the lowest speed.
inline HuntingResult conicity_result() {
  HuntingResult r = two_interval_result();
  r.conicity_curve.push_back({0.05, HuntingVerdict::stable_throughout, std::nullopt});
  for (double conicity : {0.1, 0.2}) {
    HuntingCriticalSpeed c = *r.critical;
    c.speed = 40.0 / conicity / 3.6;
    r.conicity_curve.push_back({conicity, HuntingVerdict::critical_speed_in_range, c});
  }
  r.conicity_curve.push_back({0.4, HuntingVerdict::unstable_at_lowest_speed, std::nullopt});
  return r;
}

// Zero conicity: no kinematic oscillation, Klingel's wavelength infinite.
inline HuntingResult zero_conicity_result() {
  HuntingResult r = stable_result();
  r.contacts = {hand_contact("wheelset1", 0.0)};
  return r;
}

}  // namespace railmodal::test
