// railmodal — power spectral densities of random track irregularity: the ORE/ERRI B176 low- and
// high-level spectra, the FRA track classes 1–6 and user tables, with their band RMS.
//
//   #include <railmodal/track_spectrum.hpp>
//
//   #include <cmath>
//   #include <iostream>
//
//   int main() {
//     using railmodal::TrackIrregularity;
//     const double pi = 3.14159265358979323846;
//     // ORE B176 low level, vertical level, over wavelengths 3 … 70 m
//     const railmodal::TrackSpectrum s = railmodal::TrackSpectrum::ore_b176(
//         railmodal::OreLevel::low, TrackIrregularity::vertical_level, {2 * pi / 70, 2 * pi / 3});
//     std::cout << s.name() << ": RMS " << 1000 * s.rms() << " mm; S(0.1 rad/m) = "
//               << s.density(0.1) << " m^2/(rad/m);\n  at 50 m/s, 2 Hz: "
//               << s.temporal_density(2.0, 50.0) << " m^2/Hz\n";
//   }  // prints: ORE B176 low, vertical level: RMS 1.92189 mm; S(0.1 rad/m) = 3.8118e-05 m^2/(rad/m);
//      //           at 50 m/s, 2 Hz: 7.29062e-07 m^2/Hz
//
// Conventions (the same for every spectrum, tested in tests/excitation/track_spectrum_test.cpp):
//  - Units are SI: wavenumber Ω in rad/m (Ω = 2π/λ), densities in m²/(rad/m); cross-level is
//    the height difference Δz = z_left − z_right between the two rails in metres (its density in
//    m²/(rad/m)); cross_level_angle_density gives the angle θ = Δz/(2b) for contact-point
//    spacing 2b, in rad²/(rad/m).
//  - Densities are ONE-SIDED: the variance is ∫ S(Ω) dΩ over Ω > 0 only. A density defined on
//    −∞ … ∞ (two-sided) is half of this one; a density per cycle/m (n = Ω/2π) is 2π times it:
//    S_n(n) = 2π S(2πn).
//  - At speed V, Ω = 2πf/V: the temporal one-sided density in m²/Hz is G(f) = (2π/V) S(2πf/V),
//    so that ∫ G df over the mapped band is the same variance.
//  - Every spectrum has an explicit band [Ω_low, Ω_high] (rad/m) outside which its density is
//    zero: the FRA spectra go as Ω⁻² at long wavelengths and their variance diverges without a
//    lower cut-off. The level, alignment and cross-level of one track are taken as uncorrelated.
// Sources, constants and their disagreements: docs/ride.md, "Track irregularity spectra".
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace railmodal {

/// Which irregularity a spectrum describes.
enum class TrackIrregularity {
  vertical_level,  ///< vertical profile (level) of the track, m
  alignment,       ///< lateral alignment, m
  cross_level,     ///< height difference between the rails Δz = z_left − z_right, m
};
const char* to_string(TrackIrregularity irregularity);  ///< "vertical_level", "alignment", "cross_level"
/// Inverse of to_string; std::nullopt for an unknown word.
/// Also reads the spellings before 2026-11-27, "vertical-level" and "cross-level".
std::optional<TrackIrregularity> track_irregularity_from_string(const std::string& word);

/// One component of a track's irregularity refused where it meets a system, a frequency grid or
/// a sampling, though valid on its own: it moves no degree of freedom of the model, its band
/// lies wholly outside the grid at a speed, cross-level the ride does not model on these
/// wheelsets, a band the realisation cannot sample. A std::invalid_argument (what() says why)
/// that says which component, so that a caller can place the error at that component of its
/// input (railmodal ride: at the scene's [source.alignment] table and key) without reading text.
class IrregularityComponentError : public std::invalid_argument {
 public:
  IrregularityComponentError(TrackIrregularity component, const std::string& message)
      : std::invalid_argument(message), component_(component) {}
  TrackIrregularity component() const { return component_; }

 private:
  TrackIrregularity component_;
};

/// The two ORE B176 track qualities.
enum class OreLevel { low, high };
const char* to_string(OreLevel level);  ///< "low", "high"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<OreLevel> ore_level_from_string(const std::string& word);

/// What the first column of a user table is, and so what its densities are per.
enum class SpectrumAbscissa {
  wavenumber,         ///< Ω in rad/m; density in m²/(rad/m)
  spatial_frequency,  ///< n = 1/λ in cycles/m; density in m²/(cycle/m)
  wavelength,         ///< λ in m; density in m²/(cycle/m), i.e. per unit of 1/λ (not per metre of λ)
};
const char* to_string(SpectrumAbscissa abscissa);  ///< "wavenumber", "spatial_frequency", "wavelength"
/// Inverse of to_string; std::nullopt for an unknown word.
/// Also reads "spatial-frequency", the spelling before 2026-11-27.
std::optional<SpectrumAbscissa> spectrum_abscissa_from_string(const std::string& word);

/// A band of wavenumbers, rad/m: 0 ≤ low < high < ∞.
struct WavenumberBand {
  double low = 0.0;   ///< rad/m (the longest wavelength is 2π/low)
  double high = 0.0;  ///< rad/m (the shortest wavelength is 2π/high)
  /// Returns false and explains in *why when the band is not 0 ≤ low < high < ∞.
  bool is_valid(std::string* why) const;
};

/// A one-sided spatial power spectral density of one track irregularity, zero outside its band.
/// Immutable once made; cheap to copy.
class TrackSpectrum {
 public:
  /// ORE B176 (ERRI B176, "German") spectrum of the given level. Level and alignment:
  /// S = A Ω_c² / ((Ω² + Ω_r²)(Ω² + Ω_c²)); cross-level height difference:
  /// S = 4 A_v Ω_c² Ω² / ((Ω² + Ω_r²)(Ω² + Ω_c²)(Ω² + Ω_s²)), which is (2b)² times the
  /// published angle spectrum (A_v/b²)·… and so does not depend on b. Ω_c = 0.8246,
  /// Ω_r = 0.0206, Ω_s = 0.438 rad/m; A_v = 4.032e-7 (low) / 1.080e-6 (high) and
  /// A_a = 2.119e-7 / 6.125e-7 m²·rad/m. The band is the caller's: B176 gives none, and the
  /// spectrum's variance over 0 … ∞ is finite. Throws std::invalid_argument for an invalid band.
  static TrackSpectrum ore_b176(OreLevel level, TrackIrregularity irregularity, WavenumberBand band);
  /// FRA track class 1 … 6 (6 the best) in the form of Garg & Dukkipati (1984) with k = 0.25:
  /// level S = k A_v Ω_c² / (Ω²(Ω² + Ω_c²)), alignment the same with A_a, cross-level
  /// S = 4 k A_v Ω_c² / ((Ω² + Ω_c²)(Ω² + Ω_s²)); Ω_c = 0.8245 rad/m, A and Ω_s by class
  /// (docs/ride.md), converted from cm² to m². The default band is the FRA range of
  /// wavelengths 1.524 … 304.8 m (5 … 1000 ft). Throws std::invalid_argument for a class
  /// outside 1 … 6 or an invalid band (low must be > 0 for level and alignment: Ω⁻²).
  static TrackSpectrum fra_class(int track_class, TrackIrregularity irregularity);
  static TrackSpectrum fra_class(int track_class, TrackIrregularity irregularity, WavenumberBand band);
  /// A user table of (abscissa, one-sided density) pairs in SI units (see SpectrumAbscissa),
  /// in any order, at least two points, abscissae distinct and positive, densities positive and
  /// finite. The density is interpolated linearly in log S against log Ω between neighbouring
  /// points (a power law on each segment, integrated exactly) and is ZERO outside the table's
  /// range, which is the band: nothing is extrapolated. Throws std::invalid_argument naming
  /// the offending point.
  static TrackSpectrum table(TrackIrregularity irregularity, SpectrumAbscissa abscissa,
                             const std::vector<double>& abscissae, const std::vector<double>& densities);

  TrackIrregularity irregularity() const { return irregularity_; }
  /// "ORE B176 low, vertical level", "FRA class 4, alignment", "table, cross-level".
  const std::string& name() const { return name_; }
  WavenumberBand band() const { return band_; }

  /// S(Ω), m²/(rad/m), one-sided; 0 outside the band. Throws std::invalid_argument for a
  /// negative or non-finite wavenumber.
  double density(double wavenumber) const;
  /// S_n(n) = 2π S(2πn), m²/(cycle/m): the same spectrum per cycle/m.
  double density_per_cycle(double spatial_frequency) const;
  /// G(f) = (2π/V) S(2πf/V), m²/Hz: the one-sided density in time of the irregularity under a
  /// wheel running at `speed` m/s, at `frequency` Hz. Throws std::invalid_argument for a speed
  /// that is not positive and finite or a negative frequency.
  double temporal_density(double frequency, double speed) const;
  /// θ = Δz/(2b): S_θ = S/(2b)², rad²/(rad/m), for contact_spacing = 2b in m. Throws
  /// std::invalid_argument unless this is a cross-level spectrum and the spacing is positive.
  double cross_level_angle_density(double wavenumber, double contact_spacing) const;

  /// σ² = ∫ S(Ω) dΩ over the intersection of `band` with the spectrum's band, m², integrated
  /// exactly (partial fractions for the standard spectra, power-law segments for tables).
  /// Throws std::invalid_argument for an invalid band.
  double variance(WavenumberBand band) const;
  double variance() const;                ///< over the spectrum's own band, m²
  double rms(WavenumberBand band) const;  ///< √variance(band), m
  double rms() const;                     ///< √variance(), m

 private:
  TrackSpectrum() = default;
  double indefinite_integral(double wavenumber) const;  // rational spectra only
  double table_variance(double low, double high) const;

  TrackIrregularity irregularity_ = TrackIrregularity::vertical_level;
  std::string name_;
  WavenumberBand band_;
  // Rational form S = gain · Ω^(2·numerator_power) / Π (Ω² + p_i²), p_i ≥ 0 distinct.
  double gain_ = 0.0;
  int numerator_power_ = 0;
  std::vector<double> poles_;
  // Table form (when wavenumbers_ is not empty): Ω ascending, S at each.
  std::vector<double> wavenumbers_;
  std::vector<double> densities_;
};

}  // namespace railmodal
