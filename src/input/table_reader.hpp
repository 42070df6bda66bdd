// Checked access to one TOML table: every error names file, line, column and the dotted
// key; keys nobody asked for are reported as unknown when the table is finished.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <toml.hpp>
#include <vector>

#include "input/units.hpp"
#include "railmodal/errors.hpp"

namespace railmodal::input {

/// The magnitudes a quantity may have in SI units, whatever its kind, besides zero. The same
/// band for every kind: a railway vehicle's quantities are all many decades inside it (a
/// 1e15 N/m "rigid" link, a 1e-6 m dip), and within it a product or quotient of up to ten
/// inputs (k·a², k/m, ...) stays a normal double (1e±300), so no step of the analyses
/// overflows or underflows to a subnormal (5e-324 kg read as a mass gave "rigid-body" modes).
inline constexpr double kSmallestMagnitude = 1e-30;
inline constexpr double kLargestMagnitude = 1e30;
/// Whether `si` is zero or inside [kSmallestMagnitude, kLargestMagnitude] in magnitude.
bool within_magnitudes(double si);
/// Why `si` is not: "the value ... is below any physical quantity ...", naming the band; with
/// the value as `written` in the file ("\"1e-320 cm/s^2\""), that and its SI number.
std::string magnitude_complaint(double si, const std::string& written = std::string());

class TableReader {
 public:
  TableReader(const toml::value& table, std::string file, std::string path);

  bool has(const std::string& key) const;
  /// A quantity in SI; a bare number is SI, a string carries units.
  double quantity(const std::string& key, Quantity kind);
  std::optional<double> optional_quantity(const std::string& key, Quantity kind);
  /// Like quantity(), with a check that the value is > 0 (or ≥ 0 when allow_zero).
  double positive(const std::string& key, Quantity kind, bool allow_zero = false);
  std::optional<double> optional_positive(const std::string& key, Quantity kind, bool allow_zero = false);
  std::string string(const std::string& key);
  std::optional<std::string> optional_string(const std::string& key);
  int count(const std::string& key, int minimum);
  std::optional<int> optional_count(const std::string& key, int minimum);
  /// A point [x, y, z], each a length.
  std::array<double, 3> point(const std::string& key);
  std::vector<std::string> strings(const std::string& key);
  /// An array of quantities of one kind, e.g. ["0 deg", "90 deg"].
  std::vector<double> quantities(const std::string& key, Quantity kind);
  std::optional<bool> optional_boolean(const std::string& key);
  /// The file a string names, relative to this file's folder unless absolute, normalised.
  /// Fails when it does not exist, or when the system cannot tell (a symbolic link loop, a
  /// name too long, a folder that may not be read), with the system's reason.
  std::string existing_file(const std::string& key);
  /// The value itself, for callers that keep it as written (a study's override values).
  const toml::value& raw(const std::string& key);
  /// The keys present, sorted (so that callers visit them in a fixed order).
  std::vector<std::string> keys() const;
  TableReader table(const std::string& key);
  /// An array of tables ([[key]] or key = [{...}, ...]); a single table counts as one.
  std::vector<TableReader> tables(const std::string& key);

  /// Throws for the first key that was never read, with the keys asked for and absent that it
  /// likely meant ("did you mean 'vertical_damping', 'lateral_damping' or …?").
  void finish() const;
  /// For a missing `key`: throws at a present, unread key that looks like a misspelling of it
  /// ("is 'wieght' a misspelling of it?"); returns when there is none.
  void refuse_misspelling(const std::string& key) const;

  /// Where this key's value is written (the table's place when the key is absent).
  KeyPlace place(const std::string& key) const;
  /// An InputError at this key's value (or at the table when the key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  std::string key_path(const std::string& key) const;
  const std::string& file() const { return file_; }
  /// The value `v` as quantity() reads it for `key` (the same conversion and checks), for a
  /// caller that holds a value outside any table (a study's fast path reads each variant's).
  double to_quantity(const toml::value& v, const std::string& key, Quantity kind) const;

 private:
  const toml::value& at(const std::string& key);

  const toml::value& table_;
  std::string file_;
  std::string path_;
  std::set<std::string> read_;
  /// The keys asked for (has) and absent: what an unknown key may have meant (finish).
  mutable std::vector<std::string> absent_;
};

/// Parses a TOML file; a syntax error becomes an InputError with its line and column.
toml::value parse_toml_file(const std::string& file);

}  // namespace railmodal::input
