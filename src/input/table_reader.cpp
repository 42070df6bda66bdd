#include "input/table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>

#include "input/c_locale_chars.hpp"
#include "input/input_file.hpp"
#include "input/toml_preflight.hpp"
#include "input/value_place.hpp"
#include "edit_distance.hpp"
#include "railmodal/errors.hpp"
#include "shortest_text.hpp"

namespace railmodal::input {
namespace {

// A speed written without its unit ("100", 100, 2.5e1): anything but zero, which is zero in
// every unit.
bool unitless_speed(const toml::value& v) {
  if (v.is_integer()) return v.as_integer() != 0;
  if (v.is_floating()) return v.as_floating() != 0.0;
  if (!v.is_string()) return false;
  const char* start = v.as_string().str.c_str();
  while (*start == ' ' || *start == '\t') ++start;
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  if (end == start) return false;
  while (*end == ' ' || *end == '\t') ++end;
  return *end == '\0' && value != 0.0;
}

// The number a bare speed was written as, for the message's example.
std::string written_speed_number(const toml::value& v) {
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return shortest_text(v.as_floating());
  const std::string& text = v.as_string().str;
  const size_t first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

// A value as the file writes it, for messages: a string quoted ("\"-10 km/h\""), a number as
// its shortest text.
std::string written_text(const toml::value& v) {
  if (v.is_string()) return "\"" + v.as_string().str + "\"";
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return shortest_text(v.as_floating());
  return "a " + std::string(v.is_array() ? "list" : "value");
}

const char* type_name(const toml::value& v) {
  switch (v.type()) {
    case toml::value_t::boolean: return "a boolean";
    case toml::value_t::integer: return "an integer";
    case toml::value_t::floating: return "a number";
    case toml::value_t::string: return "a string";
    case toml::value_t::array: return "an array";
    case toml::value_t::table: return "a table";
    default: return "a date or time";
  }
}

// Plain scans for the two patterns of toml11's formatted message that parse_toml_file reads.
// They replace std::regex (R"(\n\s*(\d+) \|)" and R"(\^+-*\s*(.*))", ECMAScript, searched
// once each), which made this the library's slowest file to compile, with the same matches:
// \s is the C locale's white space, \d an ASCII digit (input/c_locale_chars.hpp) and '.' any
// character but '\n' and '\r'.

// The digits of the first "\n", white space, digits, " |" in `message`.
std::optional<std::string> marker_line_digits(const std::string& message) {
  for (auto start = message.find('\n'); start != std::string::npos; start = message.find('\n', start + 1)) {
    std::size_t i = start + 1;
    while (i < message.size() && is_c_space(message[i])) ++i;
    const std::size_t first_digit = i;
    while (i < message.size() && is_ascii_digit(message[i])) ++i;
    if (i > first_digit && message.compare(i, 2, " |") == 0)
      return message.substr(first_digit, i - first_digit);
  }
  return std::nullopt;
}

// What follows the first run of carets, its dashes and white space, to the end of that line.
std::string caret_detail(const std::string& message) {
  std::size_t i = message.find('^');
  if (i == std::string::npos) return {};
  while (i < message.size() && message[i] == '^') ++i;
  while (i < message.size() && message[i] == '-') ++i;
  while (i < message.size() && is_c_space(message[i])) ++i;
  const std::size_t end = message.find_first_of("\n\r", i);
  return message.substr(i, end == std::string::npos ? std::string::npos : end - i);
}

}  // namespace

bool within_magnitudes(double si) {
  return si == 0.0 || (std::abs(si) >= kSmallestMagnitude && std::abs(si) <= kLargestMagnitude);
}

std::string magnitude_complaint(double si, const std::string& written) {
  std::ostringstream out;
  out << std::setprecision(3);
  if (!written.empty())
    out << "the value " << written << " (" << si << " in SI units) is "
        << (std::abs(si) > kLargestMagnitude ? "beyond any physical quantity (more than 1e30"
                                             : "below any physical quantity (less than 1e-30");
  else if (std::abs(si) > kLargestMagnitude)
    out << "the value is beyond any physical quantity (more than 1e30";
  else
    out << "the value " << si << " is below any physical quantity (less than 1e-30";
  out << " in SI units): a quantity is zero or of magnitude 1e-30 to 1e30 in SI units";
  return out.str();
}

TableReader::TableReader(const toml::value& table, std::string file, std::string path)
    : table_(table), file_(std::move(file)), path_(std::move(path)) {}

std::string TableReader::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

KeyPlace TableReader::place(const std::string& key) const {
  return place_of(has(key) ? table_.as_table().at(key) : table_);
}

void TableReader::fail(const std::string& key, const std::string& message) const {
  const KeyPlace where = place(key);
  throw InputError(file_, where.line, where.column, "key '" + key_path(key) + "': " + message);
}

bool TableReader::has(const std::string& key) const {
  const bool present = table_.is_table() && table_.as_table().count(key) > 0;
  // Every optional key passes here: finish's suggestions. Once every key present is read, no
  // unknown key is left to suggest for, and nothing is kept (a study reads each variant's file).
  if (!present && table_.is_table() && read_.size() < table_.as_table().size()) absent_.push_back(key);
  return present;
}

void TableReader::refuse_misspelling(const std::string& key) const {
  if (!table_.is_table()) return;
  for (const auto& [present, value] : table_.as_table())
    if (!read_.count(present) && edit_distance(present, key) <= 2) {
      const KeyPlace place = place_of(value);
      throw InputError(file_, place.line, place.column,
                       "key '" + key_path(key) + "': missing; is '" + present + "' a misspelling of it?");
    }
}

const toml::value& TableReader::at(const std::string& key) {
  if (!has(key)) {
    refuse_misspelling(key);  // point at a present key that looks like a misspelling of it
    fail(key, "missing (required)");
  }
  read_.insert(key);
  return table_.as_table().at(key);
}

double TableReader::to_quantity(const toml::value& v, const std::string& key, Quantity kind) const {
  // A speed needs its unit, in files as on the command line (README.md, "Speeds"): a bare 100
  // would be 100 m/s, 360 km/h, where the reports speak km/h.
  if (kind == Quantity::speed && unitless_speed(v))
    fail(key, "give the speed its unit, such as \"" + written_speed_number(v) + " km/h\" or \"" +
                  written_speed_number(v) + " m/s\": a bare number is not a speed");
  double value = 0.0;
  if (v.is_integer()) {
    value = static_cast<double>(v.as_integer());
  } else if (v.is_floating()) {
    value = v.as_floating();
  } else if (v.is_string()) {
    try {
      value = parse_quantity(v.as_string().str, kind);
    } catch (const std::invalid_argument& e) {
      fail(key, e.what());
    }
  } else {
    fail(key, std::string("expected ") + name_of(kind) + " such as " + example_of(kind) +
                  ", got " + type_name(v));
  }
  if (!std::isfinite(value)) fail(key, "the value is not a finite number");
  // A value written with units is quoted as written: its SI number alone ("1e-322") is not what
  // the file says.
  if (!within_magnitudes(value)) fail(key, magnitude_complaint(value, v.is_string() ? written_text(v) : std::string()));
  return value;
}

double TableReader::quantity(const std::string& key, Quantity kind) {
  return to_quantity(at(key), key, kind);
}

std::optional<double> TableReader::optional_quantity(const std::string& key, Quantity kind) {
  if (!has(key)) return std::nullopt;
  return quantity(key, kind);
}

double TableReader::positive(const std::string& key, Quantity kind, bool allow_zero) {
  const double value = quantity(key, kind);
  // The value as the file writes it ("-10 km/h"), not its SI number (-2.77778, which the audit of
  // 2026-11-27 found echoed for "-10 km/h").
  if (allow_zero ? value < 0.0 : !(value > 0.0))
    fail(key, std::string("must be ") + (allow_zero ? "zero or positive" : "positive") + ", got " +
                  written_text(table_.as_table().at(key)));
  return value;
}

std::optional<double> TableReader::optional_positive(const std::string& key, Quantity kind, bool allow_zero) {
  if (!has(key)) return std::nullopt;
  return positive(key, kind, allow_zero);
}

std::string TableReader::string(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_string()) fail(key, std::string("expected a string, got ") + type_name(v));
  return v.as_string().str;
}

std::optional<std::string> TableReader::optional_string(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return string(key);
}

int TableReader::count(const std::string& key, int minimum) {
  const toml::value& v = at(key);
  if (!v.is_integer()) fail(key, std::string("expected an integer, got ") + type_name(v));
  const auto value = v.as_integer();
  if (value < minimum || value > 1000000)
    fail(key, "must be an integer from " + std::to_string(minimum) + " to 1000000, got " +
                  std::to_string(value));
  return static_cast<int>(value);
}

std::optional<int> TableReader::optional_count(const std::string& key, int minimum) {
  if (!has(key)) return std::nullopt;
  return count(key, minimum);
}

std::array<double, 3> TableReader::point(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_array() || v.as_array().size() != 3)
    fail(key, "expected a point [x, y, z] of three lengths, such as [\"0 m\", \"0.8 m\", \"1.2 m\"]");
  std::array<double, 3> p{};
  for (int i = 0; i < 3; ++i) p[i] = to_quantity(v.as_array()[i], key, Quantity::length);
  return p;
}

std::vector<double> TableReader::quantities(const std::string& key, Quantity kind) {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, std::string("expected an array of quantities, got ") + type_name(v));
  std::vector<double> out;
  for (const auto& item : v.as_array()) out.push_back(to_quantity(item, key, kind));
  return out;
}

std::vector<std::string> TableReader::strings(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, std::string("expected an array of strings, got ") + type_name(v));
  std::vector<std::string> out;
  for (const auto& item : v.as_array()) {
    if (!item.is_string()) fail(key, "expected an array of strings");
    out.push_back(item.as_string().str);
  }
  return out;
}

std::optional<bool> TableReader::optional_boolean(const std::string& key) {
  if (!has(key)) return std::nullopt;
  const toml::value& v = at(key);
  if (!v.is_boolean()) fail(key, std::string("expected true or false, got ") + type_name(v));
  return v.as_boolean();
}

std::string TableReader::existing_file(const std::string& key) {
  const std::filesystem::path named(string(key));
  const std::string path =
      (named.is_absolute() ? named : std::filesystem::path(file_).parent_path() / named).lexically_normal().string();
  // Not std::filesystem::exists(path), which throws for a loop or a long name: that is the
  // file's fault, not ours.
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) fail(key, "no such file: " + path);
  if (error) fail(key, "cannot reach the file " + path + ": " + error.message());
  return path;
}

const toml::value& TableReader::raw(const std::string& key) { return at(key); }

std::vector<std::string> TableReader::keys() const {
  std::vector<std::string> out;
  if (table_.is_table())
    for (const auto& entry : table_.as_table()) out.push_back(entry.first);
  std::sort(out.begin(), out.end());
  return out;
}

TableReader TableReader::table(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_table()) fail(key, std::string("expected a table, got ") + type_name(v));
  return TableReader(v, file_, key_path(key));
}

std::vector<TableReader> TableReader::tables(const std::string& key) {
  const toml::value& v = at(key);
  std::vector<TableReader> out;
  if (v.is_table()) {
    out.emplace_back(v, file_, key_path(key));
    return out;
  }
  if (!v.is_array()) fail(key, std::string("expected a table or an array of tables, got ") + type_name(v));
  const auto& array = v.as_array();
  for (size_t i = 0; i < array.size(); ++i) {
    if (!array[i].is_table()) fail(key, "expected an array of tables");
    out.emplace_back(array[i], file_, key_path(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

namespace {

// Whether `word` is one of `key`'s words ("damping" of "vertical_damping").
bool is_word_of(const std::string& word, const std::string& key) {
  for (size_t at = key.find(word); at != std::string::npos; at = key.find(word, at + 1))
    if ((at == 0 || key[at - 1] == '_') && (at + word.size() == key.size() || key[at + word.size()] == '_'))
      return true;
  return false;
}

// "; did you mean 'a'?" or "; did you mean 'a', 'b' or 'c'?", from the keys asked for and absent:
// the closest within two edits (a typo: "spring_spaceing"), else those `unknown` is a word of
// (the two-axle template's [suspension] "damping" is vertical_ or lateral_damping), at most
// three; "" when none is near.
std::string did_you_mean(const std::string& unknown, std::vector<std::string> absent) {
  std::sort(absent.begin(), absent.end());
  absent.erase(std::unique(absent.begin(), absent.end()), absent.end());
  std::vector<std::string> meant;
  size_t best = 3;
  for (const std::string& key : absent)
    if (const size_t d = edit_distance(unknown, key); d < best) best = d, meant = {key};
  if (meant.empty())
    for (const std::string& key : absent)
      if (meant.size() < 3 && is_word_of(unknown, key)) meant.push_back(key);
  if (meant.empty()) return "";
  std::string text = "; did you mean ";
  for (size_t k = 0; k < meant.size(); ++k)
    text += (k == 0 ? "" : k + 1 == meant.size() ? " or " : ", ") + ("'" + meant[k] + "'");
  return text + "?";
}

}  // namespace

void TableReader::finish() const {
  if (!table_.is_table()) return;
  for (const auto& [key, value] : table_.as_table())
    if (!read_.count(key)) fail(key, "unknown key (misspelt, or not used here)" + did_you_mean(key, absent_));
}

toml::value parse_toml_file(const std::string& file) {
  const std::string content = read_input_text(file, kMaxTomlFileSize, kTomlFileSizeReason);
  check_toml_preflight(content, file);
  try {
    std::istringstream stream(content);
    // toml11 3.7.1 copies the source's name into each region it makes, one per character it
    // reads: a name longer than std::string's 15-byte inline buffer costs an allocation each
    // time (40 % of the time on long strings). Errors name `file` themselves.
    return toml::parse(stream, "-");
  } catch (const toml::exception& e) {
    // toml11 prints "[error] what\n --> file\n  12 | text\n     |    ^-- detail"; keep the
    // first line as the message and take line and column from the location.
    std::string message = e.what();
    const auto newline = message.find('\n');
    std::string head = message.substr(0, newline);
    const std::string prefix = "[error] ";
    if (head.rfind(prefix, 0) == 0) head = head.substr(prefix.size());
    int line = static_cast<int>(e.location().line());
    int column = static_cast<int>(e.location().column());
    if (e.location().file_name() == "unknown file") {
      // Fall back on the " 12 | " marker of the formatted message.
      if (const auto digits = marker_line_digits(message)) line = std::stoi(*digits);
      column = 0;
    }
    // The detail under the caret says what was expected.
    const std::string detail = caret_detail(message);
    if (!detail.empty()) head += ": " + detail;
    throw InputError(file, line, column, "TOML syntax: " + head);
  } catch (const std::exception& e) {
    throw InputError(file, 0, 0, std::string("cannot read the file: ") + e.what());
  }
}

}  // namespace railmodal::input
