// railmodal — ride-comfort frequency weightings (EN 12299 Wb and Wd as analog transfer
// functions, Sperling's B(f)), Sperling's ride index Wz and EN 12299's mean comfort N_MV.
//
//   #include <railmodal/comfort_weighting.hpp>
//
//   #include <cmath>
//   #include <complex>
//   #include <iostream>
//
//   int main() {
//     const railmodal::FrequencyWeighting wb = railmodal::en12299_wb();  // vertical
//     const std::complex<double> w = wb.response(5.0);                   // W(j2π·5 Hz)
//     std::cout << wb.name << " at 5 Hz: |W| = " << std::abs(w) << ", phase " << std::arg(w) << " rad\n";
//     // 0.3 m/s² amplitude at 5 Hz, vertical: Sperling's Wz and the weighted RMS it rests on
//     const double aw = wb.magnitude(5.0) * 0.3 / std::sqrt(2.0);
//     std::cout << "Wb-weighted RMS " << aw << " m/s^2; Sperling Wz "
//               << railmodal::sperling_wz_harmonic(0.3, 5.0, railmodal::SperlingDirection::vertical)
//               << "; N_MV " << railmodal::en12299_nmv(0.1, 0.15, aw) << "\n";
//   }  // prints: EN 12299 Wb at 5 Hz: |W| = 0.957033, phase 0.373371 rad
//      //         Wb-weighted RMS 0.203017 m/s^2; Sperling Wz 2.60698; N_MV 1.62904
//
// Units: frequencies in Hz, accelerations in m/s² (Sperling's formulas, written for cm/s²,
// are converted inside). Sources, constants and their disagreements: docs/ride.md, "Comfort
// weightings".
#pragma once

#include <complex>
#include <optional>
#include <string>

namespace railmodal {

/// The analog weighting filter of ISO 2631-1:1997 Annex A, ISO 8041 and EN 12299:2009 Annex,
/// a product of four factors with s = j2πf and ω_i = 2πf_i:
///   band-limiting high pass   H_h = s² / (s² + sω1/Q1 + ω1²)
///   band-limiting low pass    H_l = ω2² / (s² + sω2/Q2 + ω2²)
///   acceleration–velocity     H_t = (1 + s/ω3) / (1 + s/(Q4ω4) + s²/ω4²)
///   upward step               H_s = K (1 + s/(Q5ω5) + s²/ω5²) / (1 + s/(Q6ω6) + s²/ω6²)
///   W(s) = H_h H_l H_t H_s;   without a step (has_upward_step false) H_s = K.
/// The weighted acceleration is the acceleration filtered by W: a steady sine of amplitude A at
/// f becomes one of amplitude |W(j2πf)|·A, shifted by arg W.
struct FrequencyWeighting {
  std::string name;  ///< "EN 12299 Wb"
  double f1 = 0.0;   ///< high-pass corner, Hz
  double q1 = 0.0;   ///< its quality factor
  double f2 = 0.0;   ///< low-pass corner, Hz
  double q2 = 0.0;   ///< its quality factor
  double f3 = 0.0;   ///< a–v transition zero, Hz
  double f4 = 0.0;   ///< a–v transition pole pair, Hz
  double q4 = 0.0;   ///< its quality factor
  bool has_upward_step = false;
  double f5 = 0.0;    ///< upward step zero pair, Hz (when has_upward_step)
  double q5 = 0.0;    ///< its quality factor
  double f6 = 0.0;    ///< upward step pole pair, Hz (when has_upward_step)
  double q6 = 0.0;    ///< its quality factor
  double gain = 1.0;  ///< K: the step's low-frequency gain (the gain overall without a step)

  /// Returns false and explains in *why when a frequency or quality factor is not positive and
  /// finite (the step's only when has_upward_step), or the gain is not.
  bool is_valid(std::string* why) const;
  /// W(j2πf), dimensionless. Throws std::invalid_argument for an invalid weighting or a
  /// frequency that is negative or not finite.
  std::complex<double> response(double frequency) const;
  /// |W(j2πf)|.
  double magnitude(double frequency) const { return std::abs(response(frequency)); }
};

/// EN 12299:2009 Wb, vertical: f1 = 0.4, f2 = 100 Hz, Q1 = Q2 = 1/√2; f3 = f4 = 16 Hz,
/// Q4 = 0.63; upward step f5 = 2.5 Hz, Q5 = 0.8, f6 = 4 Hz, Q6 = 0.8, K = 0.4.
/// (Not ISO 2631-4 / BS 6841's Wb, which has Q4, Q5, Q6 = 0.55, 0.9, 0.95: bs6841_wb.)
FrequencyWeighting en12299_wb();
/// EN 12299:2009 Wd, lateral and longitudinal (the same as ISO 2631-1's Wd): f1 = 0.4,
/// f2 = 100 Hz, Q1 = Q2 = 1/√2; f3 = f4 = 2 Hz, Q4 = 0.63; no step, K = 1.
FrequencyWeighting en12299_wd();
/// BS 6841:1987 / ISO 2631-4:2001 Wb as ISO 8041 defines it: EN 12299's structure with
/// Q4 = 0.55, Q5 = 0.9, Q6 = 0.95 (and K = 0.4). For comparison with published tables; EN 12299
/// indices use en12299_wb.
FrequencyWeighting bs6841_wb();

/// Axis of Sperling's weighting.
enum class SperlingDirection { vertical, lateral };
const char* to_string(SperlingDirection direction);  ///< "vertical", "lateral"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<SperlingDirection> sperling_direction_from_string(const std::string& word);

/// Sperling's weighting B(f), dimensionless, f in Hz:
///   B_v(f) = 0.588 √[(1.911 f² + (0.25 f²)²) / ((1 − 0.277 f²)² + (1.563 f − 0.0368 f³)²)],
///   B_l(f) = 1.25 B_v(f).
/// Throws std::invalid_argument for a negative or non-finite frequency.
double sperling_weighting(double frequency, SperlingDirection direction);
/// Sperling's Wz of one harmonic of peak `amplitude` m/s² at `frequency` Hz:
/// Wz = (b·B(f))^0.3 with b the amplitude in cm/s². Throws std::invalid_argument for a negative
/// or non-finite amplitude or frequency.
double sperling_wz_harmonic(double amplitude, double frequency, SperlingDirection direction);
/// The filter-based (weighted RMS) form: Wz = (100·√2·a_w)^0.3 = 4.4173·a_w^0.3 for a_w the
/// RMS in m/s² of the B-weighted acceleration (the harmonic formula with b = √2 a_w; it equals
/// sperling_wz_harmonic for one sine). Throws std::invalid_argument for a negative or
/// non-finite a_w.
double sperling_wz_from_weighted_rms(double weighted_rms);

/// EN 12299:2009 simplified mean comfort N_MV = 6 √(a_XP95² + a_YP95² + a_ZP95²), the three
/// arguments the 95th percentiles (m/s²) of the 5-s RMS values of the Wd-weighted longitudinal,
/// Wd-weighted lateral and Wb-weighted vertical floor accelerations. Dimensionless (the 6 carries
/// 1/(m/s²)). Throws std::invalid_argument for a negative or non-finite percentile.
double en12299_nmv(double p95_longitudinal, double p95_lateral, double p95_vertical);

}  // namespace railmodal
