#include "input/input_warnings.hpp"

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>

#include "input/table_reader.hpp"
#include "shortest_text.hpp"

namespace railmodal::input {
namespace {

thread_local std::vector<std::string>* collected_warnings = nullptr;

// The unit a length is written in ("mm"; "" for a bare number) and its number.
struct WrittenLength {
  double number = 0.0;
  std::string unit;
};

WrittenLength written_length(const toml::value& v) {
  WrittenLength w;
  if (v.is_integer()) w.number = static_cast<double>(v.as_integer());
  if (v.is_floating()) w.number = v.as_floating();
  if (v.is_string()) {
    const char* text = v.as_string().str.c_str();
    char* end = nullptr;
    w.number = std::strtod(text, &end);
    w.unit = end;
    w.unit.erase(0, w.unit.find_first_not_of(" \t"));
    w.unit.erase(w.unit.find_last_not_of(" \t") + 1);
  }
  return w;
}

}  // namespace

WarningCollector::WarningCollector(std::vector<std::string>* into) : previous_(collected_warnings) {
  collected_warnings = into;
}

WarningCollector::~WarningCollector() { collected_warnings = previous_; }

void warn(const std::string& file, int line, int column, const std::string& message) {
  if (!collected_warnings) return;
  std::string where = file;
  if (line > 0) where += ":" + std::to_string(line) + (column > 0 ? ":" + std::to_string(column) : "");
  std::string text = where + ": warning: " + message;
  // Once: a template reads a shared table once for each element it makes (four springs).
  for (const std::string& w : *collected_warnings)
    if (w == text) return;
  collected_warnings->push_back(std::move(text));
}

void warn_at(TableReader& t, const std::string& key, const std::string& message) {
  const KeyPlace at = t.place(key);
  warn(t.file(), at.line, at.column, "key '" + t.key_path(key) + "': " + message);
}

namespace {

// A unit a written number may have been meant in, and its SI factor.
struct UnitScale {
  const char* unit;
  double factor;
};
constexpr UnitScale kLengthUnits[] = {{"mm", 1e-3}, {"cm", 1e-2}, {"m", 1.0}};
constexpr UnitScale kMassUnits[] = {{"kg", 1.0}, {"t", 1e3}};

// What warn_outside says of a value outside its band.
struct Band {
  double low;           // SI; a value inside [low, high] by magnitude is plausible
  double high;
  const char* what;     // "a wagon's dimension (...)"
  std::string limits;   // "1 mm to 50 m"
  const char* si_unit;  // what a bare number is read in: "m", "kg"
};

// "key 'k': [label ]read as 8000 m (a bare number is SI), far outside <what>; warned outside
// <limits>: did you mean "8000 mm"?" for the value `written` read as `si`, the suggested unit the
// one (of `units`) that puts the written number inside the band nearest its middle in decades.
template <size_t N>
void warn_outside(TableReader& t, const std::string& key, const std::string& label, const toml::value& written,
                  const Band& band, const UnitScale (&units)[N]) {
  const WrittenLength w = written_length(written);
  const double middle = std::log10(std::sqrt(band.low * band.high));
  std::string likely;
  double best = 1e300;
  for (const UnitScale& u : units) {
    const double value = std::abs(w.number) * u.factor;
    if (u.unit == w.unit || (w.unit.empty() && u.factor == 1.0) || value < band.low || value > band.high) continue;
    const double distance = std::abs(std::log10(value) - middle);
    if (distance < best) best = distance, likely = u.unit;
  }
  const std::string read_as = w.unit.empty() ? shortest_text(w.number) + " " + band.si_unit + " (a bare number is SI)"
                                             : shortest_text(w.number) + " " + w.unit;
  std::string message = label + "read as " + read_as + ", far outside " + band.what + "; warned outside " + band.limits;
  if (!likely.empty()) message += ": did you mean \"" + shortest_text(w.number) + " " + likely + "\"?";
  warn_at(t, key, message);
}

}  // namespace

void warn_implausible_length(TableReader& t, const std::string& key, double si, const LengthBand& band) {
  if (!collected_warnings || si == 0.0 || (std::abs(si) >= band.low && std::abs(si) <= band.high)) return;
  warn_outside(t, key, "", t.raw(key),
               {band.low, band.high, band.what,
                shortest_text(band.low * 1e3) + " mm to " + shortest_text(band.high) + " m", "m"},
               kLengthUnits);
}

void warn_implausible_mass(TableReader& t, const std::string& key, double si) {
  const MassBand& band = kBodyMass;
  if (!collected_warnings || (si >= band.low && si <= band.high)) return;
  warn_outside(t, key, "", t.raw(key),
               {band.low, band.high, band.what,
                shortest_text(band.low) + " kg to " + shortest_text(band.high / 1e3) + " t", "kg"},
               kMassUnits);
}

void warn_implausible_point(TableReader& t, const std::string& key, const std::array<double, 3>& point) {
  if (!collected_warnings) return;
  static const char* const kAxes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    // A coordinate may be zero or small (a point on the centre line); only one beyond the
    // wagon's scale is warned, y against half the widest body, x and z against its length.
    const LengthBand& band = i == 1 ? kLateralOffset : kBodyLength;
    if (std::abs(point[i]) <= band.high) continue;
    warn_outside(t, key, std::string(kAxes[i]) + " ", t.raw(key).as_array()[static_cast<size_t>(i)],
                 {band.low, band.high, band.what, "±" + shortest_text(band.high) + " m", "m"}, kLengthUnits);
  }
}

}  // namespace railmodal::input
