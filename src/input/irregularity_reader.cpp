// Reading random track irregularity (docs/scenes.md, "Track irregularity"): per component a
// standard spectrum (ORE B176 low or high level, an FRA class) over a band of wavelengths, or a
// user table of (abscissa, density) pairs with their units and sidedness.
#include "input/irregularity_reader.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "input/c_locale_chars.hpp"
#include "input/value_place.hpp"

namespace railmodal::input {
namespace {

constexpr double kPi = 3.14159265358979323846;

// `wavelengths = ["3 m", "100 m"]`: the band's shortest and longest wavelength, in either order.
WavenumberBand read_band(TableReader& t) {
  const std::vector<double> lengths = t.quantities("wavelengths", Quantity::length);
  if (lengths.size() != 2) t.fail("wavelengths", "expected two wavelengths, the shortest and the longest, such as [\"3 m\", \"100 m\"]");
  const double shortest = std::min(lengths[0], lengths[1]), longest = std::max(lengths[0], lengths[1]);
  if (!(shortest > 0.0)) t.fail("wavelengths", "a wavelength must be above zero");
  if (!(longest > shortest)) t.fail("wavelengths", "the two wavelengths must differ");
  return {2.0 * kPi / longest, 2.0 * kPi / shortest};
}

TrackSpectrum ore(TableReader& t, TrackIrregularity component) {
  const std::string word = t.string("level");
  const auto level = ore_level_from_string(word);
  if (!level) t.fail("level", "must be \"low\" or \"high\", not '" + word + "'");
  // B176 publishes no band of validity (docs/ride.md): the scene states the one it means.
  if (!t.has("wavelengths"))
    t.fail("wavelengths", "missing: ORE B176 gives no band of validity; give the wavelengths the study means, such "
                          "as wavelengths = [\"3 m\", \"100 m\"]");
  return TrackSpectrum::ore_b176(*level, component, read_band(t));
}

TrackSpectrum fra(TableReader& t, TrackIrregularity component) {
  const int track_class = t.count("class", 1);
  if (track_class > 6) t.fail("class", "FRA track classes run from 1 to 6 (6 the best), got " + std::to_string(track_class));
  if (!t.has("wavelengths")) return TrackSpectrum::fra_class(track_class, component);
  return TrackSpectrum::fra_class(track_class, component, read_band(t));
}

// The SI value of one abscissa unit for the table's abscissa kind: a wavelength in any length
// unit; a wavenumber in rad/m; a spatial frequency in cycle/m (or 1/m, which is the same).
double abscissa_scale(TableReader& t, SpectrumAbscissa abscissa) {
  const std::string unit = t.string("abscissa_unit");
  switch (abscissa) {
    case SpectrumAbscissa::wavelength:
      try {
        return parse_quantity("1 " + unit, Quantity::length);
      } catch (const std::invalid_argument& e) {
        t.fail("abscissa_unit", std::string("a wavelength's unit is a length (m, cm, mm, km): ") + e.what());
      }
    case SpectrumAbscissa::wavenumber:
      if (unit == "rad/m") return 1.0;
      t.fail("abscissa_unit", "a wavenumber's unit is rad/m, not '" + unit +
                                  "' (a table per cycle/m is abscissa = \"spatial_frequency\")");
    case SpectrumAbscissa::spatial_frequency:
      if (unit == "cycle/m" || unit == "1/m") return 1.0;
      t.fail("abscissa_unit", "a spatial frequency's unit is cycle/m (or 1/m), not '" + unit + "'");
  }
  t.fail("abscissa_unit", "unknown abscissa");
}

// A density unit read by a plain scan (it replaced std::regex
// R"(^\s*(m|cm|mm)(\^2|²)\s*/\s*\(\s*(rad|cycle)\s*/\s*m\s*\)\s*$)", matched whole, which
// made this file slow to compile), with the same matches: \s is the C locale's white space.
struct DensityUnit {
  double length = 0.0;  // the squared length's unit in metres
  bool per_cycle = false;
};

// Reads the text `word` at `at` in `unit`, advancing past it; false (`at` unchanged) otherwise.
bool read_word(std::string_view unit, std::size_t& at, std::string_view word) {
  if (unit.compare(at, word.size(), word) != 0) return false;
  at += word.size();
  return true;
}

// Moves `at` past the C locale's white space (the regular expression's \s).
void skip_density_space(std::string_view unit, std::size_t& at) {
  while (at < unit.size() && is_c_space(unit[at])) ++at;
}

std::optional<DensityUnit> read_density_unit(std::string_view unit) {
  DensityUnit u;
  std::size_t at = 0;
  skip_density_space(unit, at);
  // mm and cm before m; after m only ^2 or ² follows, so the order decides nothing else.
  if (read_word(unit, at, "mm"))
    u.length = 1e-3;
  else if (read_word(unit, at, "cm"))
    u.length = 1e-2;
  else if (read_word(unit, at, "m"))
    u.length = 1.0;
  else
    return std::nullopt;
  if (!read_word(unit, at, "^2") && !read_word(unit, at, "²")) return std::nullopt;
  skip_density_space(unit, at);
  if (!read_word(unit, at, "/")) return std::nullopt;
  skip_density_space(unit, at);
  if (!read_word(unit, at, "(")) return std::nullopt;
  skip_density_space(unit, at);
  if (read_word(unit, at, "cycle"))
    u.per_cycle = true;
  else if (!read_word(unit, at, "rad"))
    return std::nullopt;
  skip_density_space(unit, at);
  if (!read_word(unit, at, "/")) return std::nullopt;
  skip_density_space(unit, at);
  if (!read_word(unit, at, "m")) return std::nullopt;
  skip_density_space(unit, at);
  if (!read_word(unit, at, ")")) return std::nullopt;
  skip_density_space(unit, at);
  if (at != unit.size()) return std::nullopt;
  return u;
}

// `density_unit = "mm^2/(cycle/m)"`: a squared length per rad/m or per cycle/m. Returns the SI
// factor to the density TrackSpectrum::table takes for `abscissa` (per rad/m for a wavenumber,
// per cycle/m otherwise): a density per cycle/m is 2π times the same spectrum per rad/m.
double density_scale(TableReader& t, SpectrumAbscissa abscissa) {
  const std::string text = t.string("density_unit");
  const std::optional<DensityUnit> unit = read_density_unit(text);
  if (!unit)
    t.fail("density_unit", "expected a squared length per rad/m or per cycle/m, such as \"m^2/(rad/m)\" or "
                           "\"mm^2/(cycle/m)\", not '" + text + "'");
  const bool wants_per_cycle = abscissa != SpectrumAbscissa::wavenumber;
  double factor = unit->length * unit->length;
  if (unit->per_cycle && !wants_per_cycle) factor /= 2.0 * kPi;  // S(Ω) = S_n(Ω/2π)/2π
  if (!unit->per_cycle && wants_per_cycle) factor *= 2.0 * kPi;  // S_n(n) = 2π S(2πn)
  return factor;
}

TrackSpectrum table(TableReader& t, TrackIrregularity component) {
  const std::string word = t.string("abscissa");
  const auto abscissa = spectrum_abscissa_from_string(word);
  if (!abscissa) t.fail("abscissa", "must be wavenumber, spatial_frequency or wavelength, not '" + word + "'");
  const double x_scale = abscissa_scale(t, *abscissa);
  double s_scale = density_scale(t, *abscissa);
  // A two-sided density (on −∞ … ∞) holds half the variance on Ω > 0: doubled to one-sided.
  const int sides = t.optional_count("sides", 1).value_or(1);
  if (sides > 2) t.fail("sides", "is 1 (one-sided, the default) or 2 (two-sided, defined on both signs)");
  if (sides == 2) s_scale *= 2.0;
  const toml::value& points = t.raw("points");
  if (!points.is_array() || points.as_array().size() < 2)
    t.fail("points", "expected at least two [abscissa, density] pairs, such as [[100, 2.5e-4], [10, 1.1e-6]]");
  std::vector<double> x, s;
  for (const toml::value& p : points.as_array()) {
    auto number = [&](const toml::value& v) -> std::optional<double> {
      if (v.is_floating()) return v.as_floating();
      if (v.is_integer()) return static_cast<double>(v.as_integer());
      return std::nullopt;
    };
    const bool pair = p.is_array() && p.as_array().size() == 2;
    const auto a = pair ? number(p.as_array()[0]) : std::nullopt;
    const auto d = pair ? number(p.as_array()[1]) : std::nullopt;
    if (!a || !d) {
      const KeyPlace where = place_of(p);
      throw InputError(t.file(), where.line, where.column,
                       "key '" + t.key_path("points") + "': each point is a pair of numbers [abscissa, density] in "
                                                        "abscissa_unit and density_unit");
    }
    x.push_back(*a * x_scale);
    s.push_back(*d * s_scale);
  }
  try {
    return TrackSpectrum::table(component, *abscissa, x, s);
  } catch (const std::invalid_argument& e) {
    t.fail("points", e.what());
  }
}

TrackSpectrum spectrum_of(TableReader& c, TrackIrregularity component) {
  const std::string kind = c.string("spectrum");
  if (kind == "ore_b176" || kind == "ore-b176") return ore(c, component);  // "ore-b176": before 2026-11-27
  if (kind == "fra") return fra(c, component);
  if (kind == "table") return table(c, component);
  c.fail("spectrum", "unknown spectrum '" + kind + "' (ore_b176, fra, table)");
}

TrackSpectrum component_spectrum(TableReader c, TrackIrregularity component) {
  try {
    TrackSpectrum s = spectrum_of(c, component);
    c.finish();
    return s;
  } catch (const std::invalid_argument& e) {
    // TrackSpectrum's own refusal (a band FRA cannot take): at the band's key when given.
    c.fail(c.has("wavelengths") ? "wavelengths" : "spectrum", e.what());
  }
}

}  // namespace

IrregularitySource read_irregularity(TableReader& t) {
  IrregularitySource source;
  for (TrackIrregularity component :
       {TrackIrregularity::vertical_level, TrackIrregularity::alignment, TrackIrregularity::cross_level}) {
    const std::string key = to_string(component);
    if (!t.has(key)) continue;
    TrackSpectrum s = component_spectrum(t.table(key), component);
    (component == TrackIrregularity::vertical_level ? source.spectra.vertical_level
     : component == TrackIrregularity::alignment    ? source.spectra.alignment
                                                    : source.spectra.cross_level) = std::move(s);
  }
  if (t.has("geometry")) source.geometry_file = t.existing_file("geometry");
  if (!source.spectra.vertical_level && !source.spectra.alignment && !source.spectra.cross_level &&
      source.geometry_file.empty())
    t.fail("kind", "an irregularity source needs at least one of [source.vertical_level], [source.alignment], "
                   "[source.cross_level] (each a spectrum), or geometry = \"FILE.csv\" (measured track)");
  return source;
}

}  // namespace railmodal::input
