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

void warn_implausible_length(TableReader& t, const std::string& key, double si, const LengthBand& band) {
  if (!collected_warnings || si == 0.0 || (std::abs(si) >= band.low && std::abs(si) <= band.high)) return;
  const WrittenLength w = written_length(t.raw(key));
  // The unit that puts the written number inside the band, nearest its middle (in decades).
  static const std::pair<const char*, double> kUnits[] = {{"mm", 1e-3}, {"cm", 1e-2}, {"m", 1.0}};
  const double middle = std::log10(std::sqrt(band.low * band.high));
  std::string likely;
  double best = 1e300;
  for (const auto& [unit, scale] : kUnits) {
    const double value = std::abs(w.number) * scale;
    if (unit == w.unit || (w.unit.empty() && scale == 1.0) || value < band.low || value > band.high) continue;
    const double distance = std::abs(std::log10(value) - middle);
    if (distance < best) best = distance, likely = unit;
  }
  const std::string read_as = w.unit.empty() ? shortest_text(w.number) + " m (a bare number is SI)"
                                             : shortest_text(w.number) + " " + w.unit;
  std::string message = "read as " + read_as + ", far outside " + band.what + "; warned outside " +
                        shortest_text(band.low * 1e3) + " mm to " + shortest_text(band.high) + " m";
  if (!likely.empty()) message += ": did you mean \"" + shortest_text(w.number) + " " + likely + "\"?";
  warn_at(t, key, message);
}

}  // namespace railmodal::input
