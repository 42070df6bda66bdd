// Track irregularity spectra: the published constants, the conversions between conventions, and
// exact band integrals. Sources and derivations: docs/ride.md, "Track irregularity spectra".
#include "railmodal/track_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ORE B176 (ERRI B176), "Bogies with steered or steering wheelsets", Report RP 1 (Utrecht,
// 1989), as given by two independent public implementations (docs/ride.md, T1 and T2; T2 rounds
// Ω_c to 0.825). Rad/m, and m²·rad/m for the A's.
constexpr double kOreOmegaC = 0.8246;
constexpr double kOreOmegaR = 0.0206;
constexpr double kOreOmegaS = 0.438;
constexpr double kOreVertical[2] = {4.032e-7, 1.080e-6};   // low, high
constexpr double kOreAlignment[2] = {2.119e-7, 6.125e-7};  // low, high

// FRA track classes in the form of Garg & Dukkipati, "Dynamics of Railway Vehicle Systems"
// (Academic Press, 1984): k = 0.25, Ω_c = 0.8245 rad/m, A in cm²·rad/m. A_v for all classes
// from two public implementations (T7, T8); A_a and Ω_s from one (T7; class 6 Ω_s also T10).
constexpr double kFraK = 0.25;
constexpr double kFraOmegaC = 0.8245;
constexpr double kFraVertical[6] = {1.2107, 1.0181, 0.6816, 0.5376, 0.2095, 0.0339};
constexpr double kFraAlignment[6] = {3.3634, 1.2107, 0.4128, 0.3027, 0.0762, 0.0339};
constexpr double kFraOmegaS[6] = {0.6046, 0.9308, 0.8520, 1.1312, 0.8209, 0.4380};
constexpr double kSquareCentimetre = 1e-4;  // m²

void require_band(const WavenumberBand& band, const char* what) {
  std::string why;
  if (!band.is_valid(&why)) throw std::invalid_argument(std::string(what) + ": " + why);
}

void require_wavenumber(double wavenumber) {
  if (!std::isfinite(wavenumber) || wavenumber < 0.0)
    throw std::invalid_argument("track spectrum: wavenumber must be finite and >= 0 rad/m");
}

std::string describe(TrackIrregularity irregularity) {
  switch (irregularity) {
    case TrackIrregularity::vertical_level:
      return "vertical level";
    case TrackIrregularity::alignment:
      return "alignment";
    case TrackIrregularity::cross_level:
      return "cross-level";
  }
  return "";
}

}  // namespace

const char* to_string(TrackIrregularity irregularity) {
  switch (irregularity) {
    case TrackIrregularity::vertical_level:
      return "vertical_level";
    case TrackIrregularity::alignment:
      return "alignment";
    case TrackIrregularity::cross_level:
      return "cross_level";
  }
  return "";
}

std::optional<TrackIrregularity> track_irregularity_from_string(const std::string& word) {
  for (TrackIrregularity i :
       {TrackIrregularity::vertical_level, TrackIrregularity::alignment, TrackIrregularity::cross_level})
    if (word == to_string(i)) return i;
  // The hyphenated words before 2026-11-27 (the vocabulary is in underscores: docs/input.md).
  if (word == "vertical-level") return TrackIrregularity::vertical_level;
  if (word == "cross-level") return TrackIrregularity::cross_level;
  return std::nullopt;
}

const char* to_string(OreLevel level) { return level == OreLevel::low ? "low" : "high"; }

std::optional<OreLevel> ore_level_from_string(const std::string& word) {
  if (word == "low") return OreLevel::low;
  if (word == "high") return OreLevel::high;
  return std::nullopt;
}

const char* to_string(SpectrumAbscissa abscissa) {
  switch (abscissa) {
    case SpectrumAbscissa::wavenumber:
      return "wavenumber";
    case SpectrumAbscissa::spatial_frequency:
      return "spatial_frequency";
    case SpectrumAbscissa::wavelength:
      return "wavelength";
  }
  return "";
}

std::optional<SpectrumAbscissa> spectrum_abscissa_from_string(const std::string& word) {
  for (SpectrumAbscissa a :
       {SpectrumAbscissa::wavenumber, SpectrumAbscissa::spatial_frequency, SpectrumAbscissa::wavelength})
    if (word == to_string(a)) return a;
  if (word == "spatial-frequency") return SpectrumAbscissa::spatial_frequency;  // the spelling before 2026-11-27
  return std::nullopt;
}

bool WavenumberBand::is_valid(std::string* why) const {
  if (std::isfinite(low) && std::isfinite(high) && low >= 0.0 && low < high) return true;
  if (why) {
    std::ostringstream out;
    out << "band [" << low << ", " << high << "] rad/m must satisfy 0 <= low < high < infinity";
    *why = out.str();
  }
  return false;
}

TrackSpectrum TrackSpectrum::ore_b176(OreLevel level, TrackIrregularity irregularity, WavenumberBand band) {
  require_band(band, "ORE B176 spectrum");
  const int l = level == OreLevel::low ? 0 : 1;
  TrackSpectrum s;
  s.irregularity_ = irregularity;
  s.name_ = std::string("ORE B176 ") + to_string(level) + ", " + describe(irregularity);
  s.band_ = band;
  const double c2 = kOreOmegaC * kOreOmegaC;
  switch (irregularity) {
    case TrackIrregularity::vertical_level:
    case TrackIrregularity::alignment:
      s.gain_ = (irregularity == TrackIrregularity::alignment ? kOreAlignment[l] : kOreVertical[l]) * c2;
      s.poles_ = {kOreOmegaR, kOreOmegaC};
      break;
    case TrackIrregularity::cross_level:
      // B176 gives the angle θ = Δz/(2b) with A_v/b²; the height difference carries (2b)².
      s.gain_ = 4.0 * kOreVertical[l] * c2;
      s.numerator_power_ = 1;
      s.poles_ = {kOreOmegaR, kOreOmegaC, kOreOmegaS};
      break;
  }
  return s;
}

TrackSpectrum TrackSpectrum::fra_class(int track_class, TrackIrregularity irregularity) {
  return fra_class(track_class, irregularity, {2.0 * kPi / 304.8, 2.0 * kPi / 1.524});
}

TrackSpectrum TrackSpectrum::fra_class(int track_class, TrackIrregularity irregularity, WavenumberBand band) {
  if (track_class < 1 || track_class > 6)
    throw std::invalid_argument("FRA spectrum: track class must be 1 ... 6, got " + std::to_string(track_class));
  require_band(band, "FRA spectrum");
  if (irregularity != TrackIrregularity::cross_level && band.low <= 0.0)
    throw std::invalid_argument("FRA spectrum: the " + describe(irregularity) +
                                " density goes as 1/Omega^2, so the band needs low > 0 rad/m");
  const int i = track_class - 1;
  TrackSpectrum s;
  s.irregularity_ = irregularity;
  s.name_ = "FRA class " + std::to_string(track_class) + ", " + describe(irregularity);
  s.band_ = band;
  const double c2 = kFraOmegaC * kFraOmegaC;
  switch (irregularity) {
    case TrackIrregularity::vertical_level:
    case TrackIrregularity::alignment:
      s.gain_ = kFraK * (irregularity == TrackIrregularity::alignment ? kFraAlignment[i] : kFraVertical[i]) *
                kSquareCentimetre * c2;
      s.poles_ = {0.0, kFraOmegaC};
      break;
    case TrackIrregularity::cross_level:
      s.gain_ = 4.0 * kFraK * kFraVertical[i] * kSquareCentimetre * c2;
      s.poles_ = {kFraOmegaC, kFraOmegaS[i]};
      break;
  }
  return s;
}

TrackSpectrum TrackSpectrum::table(TrackIrregularity irregularity, SpectrumAbscissa abscissa,
                                   const std::vector<double>& abscissae, const std::vector<double>& densities) {
  if (abscissae.size() != densities.size())
    throw std::invalid_argument("track spectrum table: " + std::to_string(abscissae.size()) + " abscissae but " +
                                std::to_string(densities.size()) + " densities");
  if (abscissae.size() < 2) throw std::invalid_argument("track spectrum table: needs at least two points");
  std::vector<std::pair<double, double>> points;
  for (std::size_t k = 0; k < abscissae.size(); ++k) {
    const double x = abscissae[k], y = densities[k];
    if (!std::isfinite(x) || x <= 0.0 || !std::isfinite(y) || y <= 0.0) {
      std::ostringstream out;
      out << "track spectrum table: point " << k + 1 << " (" << x << ", " << y
          << ") needs a positive finite abscissa and a positive finite density (log-log interpolation)";
      throw std::invalid_argument(out.str());
    }
    // A density per cycle/m is 2π times the density per rad/m of the same spectrum.
    switch (abscissa) {
      case SpectrumAbscissa::wavenumber:
        points.emplace_back(x, y);
        break;
      case SpectrumAbscissa::spatial_frequency:
        points.emplace_back(2.0 * kPi * x, y / (2.0 * kPi));
        break;
      case SpectrumAbscissa::wavelength:
        points.emplace_back(2.0 * kPi / x, y / (2.0 * kPi));
        break;
    }
  }
  std::sort(points.begin(), points.end());
  for (std::size_t k = 1; k < points.size(); ++k)
    if (points[k].first == points[k - 1].first) {
      std::ostringstream out;
      out << "track spectrum table: two points at the same wavenumber " << points[k].first << " rad/m";
      throw std::invalid_argument(out.str());
    }
  TrackSpectrum s;
  s.irregularity_ = irregularity;
  s.name_ = "table, " + describe(irregularity);
  s.band_ = {points.front().first, points.back().first};
  for (const auto& [omega, density] : points) {
    s.wavenumbers_.push_back(omega);
    s.densities_.push_back(density);
  }
  return s;
}

double TrackSpectrum::density(double wavenumber) const {
  require_wavenumber(wavenumber);
  if (wavenumber < band_.low || wavenumber > band_.high) return 0.0;
  if (!wavenumbers_.empty()) {
    // The segment holding Ω; on it S = S_k (Ω/Ω_k)^β.
    const auto upper = std::upper_bound(wavenumbers_.begin(), wavenumbers_.end(), wavenumber);
    const std::size_t k = upper == wavenumbers_.end() ? wavenumbers_.size() - 2
                                                      : static_cast<std::size_t>(upper - wavenumbers_.begin()) - 1;
    const double beta = std::log(densities_[k + 1] / densities_[k]) / std::log(wavenumbers_[k + 1] / wavenumbers_[k]);
    return densities_[k] * std::pow(wavenumber / wavenumbers_[k], beta);
  }
  const double x = wavenumber * wavenumber;
  double value = gain_ * (numerator_power_ == 1 ? x : 1.0);
  for (double p : poles_) value /= x + p * p;
  return value;
}

double TrackSpectrum::density_per_cycle(double spatial_frequency) const {
  return 2.0 * kPi * density(2.0 * kPi * spatial_frequency);
}

double TrackSpectrum::temporal_density(double frequency, double speed) const {
  if (!std::isfinite(speed) || speed <= 0.0)
    throw std::invalid_argument("track spectrum: speed must be positive and finite m/s");
  if (!std::isfinite(frequency) || frequency < 0.0)
    throw std::invalid_argument("track spectrum: frequency must be finite and >= 0 Hz");
  // Ω = 2πf/V maps df onto dΩ = (2π/V) df, so G df = S dΩ.
  return 2.0 * kPi / speed * density(2.0 * kPi * frequency / speed);
}

double TrackSpectrum::cross_level_angle_density(double wavenumber, double contact_spacing) const {
  if (irregularity_ != TrackIrregularity::cross_level)
    throw std::invalid_argument("track spectrum: " + name_ + " is not a cross-level spectrum");
  if (!std::isfinite(contact_spacing) || contact_spacing <= 0.0)
    throw std::invalid_argument("track spectrum: contact spacing must be positive and finite m");
  return density(wavenumber) / (contact_spacing * contact_spacing);
}

// Partial fractions in x = Ω²: g x^m / Π(x + p_i²) = Σ α_i / (x + p_i²) with
// α_i = g (−p_i²)^m / Π_{j≠i} (p_j² − p_i²) (numerator degree below the denominator's, poles
// distinct). ∫ dΩ/(Ω² + p²) = atan(Ω/p)/p, and −1/Ω for p = 0.
double TrackSpectrum::indefinite_integral(double wavenumber) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < poles_.size(); ++i) {
    const double pi2 = poles_[i] * poles_[i];
    double alpha = gain_ * (numerator_power_ == 1 ? -pi2 : 1.0);
    for (std::size_t j = 0; j < poles_.size(); ++j)
      if (j != i) alpha /= poles_[j] * poles_[j] - pi2;
    sum += alpha * (poles_[i] == 0.0 ? -1.0 / wavenumber : std::atan(wavenumber / poles_[i]) / poles_[i]);
  }
  return sum;
}

// Each segment S = S_k (Ω/Ω_k)^β integrates to S_k Ω_k/(β+1) [(b/Ω_k)^(β+1) − (a/Ω_k)^(β+1)],
// or S_k Ω_k ln(b/a) when β = −1.
double TrackSpectrum::table_variance(double low, double high) const {
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < wavenumbers_.size(); ++k) {
    const double a = std::max(low, wavenumbers_[k]), b = std::min(high, wavenumbers_[k + 1]);
    if (a >= b) continue;
    const double w = wavenumbers_[k], s = densities_[k];
    const double beta = std::log(densities_[k + 1] / s) / std::log(wavenumbers_[k + 1] / w);
    if (std::abs(beta + 1.0) < 1e-12)
      sum += s * w * std::log(b / a);
    else
      sum += s * w / (beta + 1.0) * (std::pow(b / w, beta + 1.0) - std::pow(a / w, beta + 1.0));
  }
  return sum;
}

double TrackSpectrum::variance(WavenumberBand band) const {
  require_band(band, "track spectrum variance");
  const double low = std::max(band.low, band_.low), high = std::min(band.high, band_.high);
  if (low >= high) return 0.0;
  if (!wavenumbers_.empty()) return table_variance(low, high);
  return indefinite_integral(high) - indefinite_integral(low);
}

double TrackSpectrum::variance() const { return variance(band_); }
double TrackSpectrum::rms(WavenumberBand band) const { return std::sqrt(variance(band)); }
double TrackSpectrum::rms() const { return std::sqrt(variance()); }

}  // namespace railmodal
