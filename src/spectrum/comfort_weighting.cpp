// Ride-comfort weightings: the analog filters of EN 12299 / ISO 2631-1 / ISO 8041, Sperling's
// B(f), Wz and N_MV. Sources and derivations: docs/ride.md, "Comfort weightings".
#include "railmodal/comfort_weighting.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

void require_nonnegative(double x, const char* what) {
  if (!std::isfinite(x) || x < 0.0) throw std::invalid_argument(std::string(what) + " must be finite and >= 0");
}

// The four-factor structure with Q1 = Q2 = 1/√2: the band limits are second-order Butterworth
// filters (ISO 8041 gives 1/√2 exactly; ISO 2631-4 and ENV 12299 print the rounded 0.71).
FrequencyWeighting band_limited(const char* name, double f34, double q4) {
  FrequencyWeighting w;
  w.name = name;
  w.f1 = 0.4;
  w.q1 = 1.0 / std::sqrt(2.0);
  w.f2 = 100.0;
  w.q2 = 1.0 / std::sqrt(2.0);
  w.f3 = f34;
  w.f4 = f34;
  w.q4 = q4;
  return w;
}

FrequencyWeighting with_step(FrequencyWeighting w, double q5, double q6) {
  w.has_upward_step = true;
  w.f5 = 2.5;
  w.q5 = q5;
  w.f6 = 4.0;
  w.q6 = q6;
  w.gain = 0.4;  // low-frequency gain; at high frequency K (f6/f5)² = 1.024, ISO 8041's K
  return w;
}

// 1 + s/(Qω) + s²/ω², the normalised second-order factor.
std::complex<double> quadratic(std::complex<double> s, double f, double q) {
  const double w = 2.0 * kPi * f;
  return 1.0 + s / (q * w) + s * s / (w * w);
}

}  // namespace

bool FrequencyWeighting::is_valid(std::string* why) const {
  // The first bad field's text, built only then: response() checks at every frequency, and a
  // stream constructed per call was most of a ride grid's weighting cost.
  std::string bad;
  const auto check = [&](double value, const char* field) {
    if (positive_finite(value) || !bad.empty()) return;
    std::ostringstream out;
    out << field << " must be positive and finite, got " << value;
    bad = out.str();
  };
  check(f1, "f1");
  check(q1, "q1");
  check(f2, "f2");
  check(q2, "q2");
  check(f3, "f3");
  check(f4, "f4");
  check(q4, "q4");
  if (has_upward_step) {
    check(f5, "f5");
    check(q5, "q5");
    check(f6, "f6");
    check(q6, "q6");
  }
  check(gain, "gain");
  if (bad.empty()) return true;
  if (why) *why = name + ": " + bad;
  return false;
}

std::complex<double> FrequencyWeighting::response(double frequency) const {
  std::string why;
  if (!is_valid(&why)) throw std::invalid_argument("FrequencyWeighting: " + why);
  require_nonnegative(frequency, "FrequencyWeighting: frequency");
  const std::complex<double> s(0.0, 2.0 * kPi * frequency);
  const double w1 = 2.0 * kPi * f1, w2 = 2.0 * kPi * f2, w3 = 2.0 * kPi * f3;
  const std::complex<double> high_pass = s * s / (s * s + s * w1 / q1 + w1 * w1);
  const std::complex<double> low_pass = w2 * w2 / (s * s + s * w2 / q2 + w2 * w2);
  const std::complex<double> transition = (1.0 + s / w3) / quadratic(s, f4, q4);
  const std::complex<double> step = has_upward_step ? quadratic(s, f5, q5) / quadratic(s, f6, q6) : 1.0;
  return high_pass * low_pass * transition * gain * step;
}

// EN 12299:2009 Annex (filter definitions), read from two independent implementations
// (comfpy filters.py; ENV 12299 env12299.m): docs/ride.md.
FrequencyWeighting en12299_wb() { return with_step(band_limited("EN 12299 Wb", 16.0, 0.63), 0.8, 0.8); }
FrequencyWeighting en12299_wd() { return band_limited("EN 12299 Wd", 2.0, 0.63); }
// ISO 8041 Table (as reprinted in the Larson Davis HVM200 manual), BS 6841:1987: docs/ride.md.
FrequencyWeighting bs6841_wb() { return with_step(band_limited("BS 6841 Wb", 16.0, 0.55), 0.9, 0.95); }

const char* to_string(SperlingDirection direction) {
  return direction == SperlingDirection::vertical ? "vertical" : "lateral";
}

std::optional<SperlingDirection> sperling_direction_from_string(const std::string& word) {
  if (word == "vertical") return SperlingDirection::vertical;
  if (word == "lateral") return SperlingDirection::lateral;
  return std::nullopt;
}

double sperling_weighting(double frequency, SperlingDirection direction) {
  require_nonnegative(frequency, "Sperling weighting: frequency");
  const double f = frequency, f2 = f * f;
  const double numerator = 1.911 * f2 + (0.25 * f2) * (0.25 * f2);
  const double real = 1.0 - 0.277 * f2, imaginary = 1.563 * f - 0.0368 * f2 * f;
  const double vertical = 0.588 * std::sqrt(numerator / (real * real + imaginary * imaginary));
  return direction == SperlingDirection::vertical ? vertical : 1.25 * vertical;
}

double sperling_wz_harmonic(double amplitude, double frequency, SperlingDirection direction) {
  require_nonnegative(amplitude, "Sperling Wz: amplitude");
  constexpr double kCentimetresPerMetre = 100.0;  // Sperling's b is in cm/s²
  return std::pow(kCentimetresPerMetre * amplitude * sperling_weighting(frequency, direction), 0.3);
}

double sperling_wz_from_weighted_rms(double weighted_rms) {
  require_nonnegative(weighted_rms, "Sperling Wz: weighted RMS");
  // A sine of RMS a_w has amplitude √2 a_w; in cm/s² that is 100√2 a_w.
  return std::pow(100.0 * std::sqrt(2.0) * weighted_rms, 0.3);
}

double en12299_nmv(double p95_longitudinal, double p95_lateral, double p95_vertical) {
  require_nonnegative(p95_longitudinal, "N_MV: longitudinal P95");
  require_nonnegative(p95_lateral, "N_MV: lateral P95");
  require_nonnegative(p95_vertical, "N_MV: vertical P95");
  return 6.0 * std::sqrt(p95_longitudinal * p95_longitudinal + p95_lateral * p95_lateral + p95_vertical * p95_vertical);
}

}  // namespace railmodal
