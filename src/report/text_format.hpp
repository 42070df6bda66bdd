// Text helpers shared by the report writers.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "railmodal/vehicle.hpp"

namespace railmodal::report {

/// km/h per m/s: speeds are SI inside and km/h in the reports (docs/product.md).
constexpr double kKmh = 3.6;

/// Whether a CSV field must be quoted: it holds a comma, quote or line break (RFC 4180).
inline bool csv_needs_quotes(std::string_view text) { return text.find_first_of(",\"\n\r") != std::string_view::npos; }

/// csv_field(text) appended to `row`, a field that needs no quotes without a copy (a study's CSV
/// writes a dozen fields a variant, CsvWriter every field of every file).
inline void append_csv_field(std::string* row, std::string_view text) {
  if (!csv_needs_quotes(text)) {
    row->append(text);
    return;
  }
  *row += '"';
  for (char c : text) {
    if (c == '"') *row += '"';
    *row += c;
  }
  *row += '"';
}

/// A CSV field, quoted when it holds a comma, quote or line break, a quote doubled (RFC 4180).
inline std::string csv_field(const std::string& text) {
  if (!csv_needs_quotes(text)) return text;
  std::string quoted;
  append_csv_field(&quoted, text);
  return quoted;
}

/// csv_field(text) written to `out`, a field that needs no quotes without a copy (a study's CSV
/// writes a dozen fields a variant).
inline void write_csv_field(std::ostream& out, const std::string& text) {
  if (csv_needs_quotes(text)) out << csv_field(text);
  else out << text;
}

/// A CSV column heading with its unit, "name [unit]" ("body.bounce [m]", "speed [km/h]"); the
/// bare name for a column without a unit (a count, a ratio, a name) or whose unit is not known
/// (""). Every CSV railmodal writes heads its columns so (docs/input.md, "Output files").
inline std::string csv_heading(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

/// The SI unit of a vehicle DOF's displacement, from the motion its label ends with
/// ("bogie1.pitch": rad, "body.bounce": m); "" for a label naming no motion (a matrix model's
/// "dof1", in whatever units its matrices are).
inline std::string displacement_unit(const std::string& label) {
  const std::optional<Motion> motion = motion_from_string(label.substr(label.rfind('.') + 1));
  if (!motion) return "";
  return *motion == Motion::roll || *motion == Motion::pitch || *motion == Motion::yaw ? "rad" : "m";
}

/// The most characters significant and fixed write for a precision up to kMaxPrecision.
constexpr int kMaxPrecision = 40;

/// `value` with `digits` (at most kMaxPrecision) significant digits, as printf's %.<digits>g
/// writes it ("0.1235", "1.235e+05", "inf", "nan"): std::to_chars with a precision writes
/// printf's text, without a stream or the locale. −0 is written "0", as every writer writes it.
inline std::string significant(double value, int digits) {
  if (value == 0.0) value = 0.0;  // −0 → 0
  char text[2 * kMaxPrecision];  // sign, digits, point, "e-308", or "0.000" before 40 digits
  return std::string(text, std::to_chars(text, text + sizeof text, value, std::chars_format::general, digits).ptr);
}

/// `value` with `decimals` (at most kMaxPrecision) digits after the point, as printf's
/// %.<decimals>f writes it; round-off never prints as "-0.0". From 1e9 on, in scientific
/// notation with as many digits after the point (%.<decimals>e): a stiff link's ω of 1e150
/// printed fixed was 150 digits, none of them meaningful past the 16th.
inline std::string fixed(double value, int decimals) {
  char text[2 * kMaxPrecision];  // below 1e9: sign, 9 digits, point and decimals
  const auto format = std::abs(value) >= 1e9 ? std::chars_format::scientific : std::chars_format::fixed;
  const char* end = std::to_chars(text, text + sizeof text, value, format, decimals).ptr;
  const char* first = text;
  // A negative value that rounds to zero ("-0.00") is written without its sign.
  if (*first == '-' && std::all_of(first + 1, end, [](char c) { return c == '0' || c == '.'; })) ++first;
  return std::string(first, end);
}

/// A source as a chart's legend or title names it, with what tells two of a kind apart: its
/// number in the scene from 1, its kind in words and its fundamental wavelength ("[1] rail
/// joints, Λ = 18 m"), so that a reader of the chart need not look it up in the Sources table
/// (user audit 2026-11-28b, F8). The tables keep "[1] rail_joints" beside that table.
inline std::string source_legend(int index, std::string kind, double wavelength_m) {
  std::replace(kind.begin(), kind.end(), '_', ' ');
  return "[" + std::to_string(index + 1) + "] " + kind + ", Λ = " + significant(wavelength_m, 5) + " m";
}

/// A table cell: `text` right-aligned in `width` characters, or after one space when it is
/// wider, so that a large number never runs into the column before it.
inline std::string right_cell(const std::string& text, size_t width) {
  return text.size() < width ? std::string(width - text.size(), ' ') + text : " " + text;
}

/// `text` left-aligned in `width` characters, or followed by one space when it is wider.
inline std::string left_cell(const std::string& text, size_t width) {
  return text.size() < width ? text + std::string(width - text.size(), ' ') : text + " ";
}

}  // namespace railmodal::report
