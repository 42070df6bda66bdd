// Matrix Market reader: the subset finite-element tools export for M, C and K (square,
// real or integer, coordinate or array, general or symmetric), with every error located at
// its file, line and column. Format: https://math.nist.gov/MatrixMarket/formats.html.
#include "railmodal/matrix_market.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

#include "input/input_file.hpp"
#include "input/table_reader.hpp"
#include "input/utf8.hpp"
#include "railmodal/errors.hpp"

namespace railmodal {
namespace {

constexpr const char* kBanner = "%%MatrixMarket matrix coordinate real general";
// A bigger size line is a corrupt file, not a model: the sparse matrix alone would need
// 4 bytes per row before a single entry is read.
constexpr long long kMaxRows = 10'000'000;

struct Token {
  std::string_view text;
  int column = 0;  // 1-based
};

std::vector<Token> split(std::string_view line) {
  std::vector<Token> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return tokens;
}

std::string lower(std::string_view word) {
  std::string out(word);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string quoted(std::string_view text) {
  // A corrupt token could be long: quote the start of it only.
  constexpr size_t kShown = 40;
  return "'" + std::string(text.substr(0, kShown)) + (text.size() > kShown ? "...'" : "'");
}

// A line longer than this is not a Matrix Market line (an entry takes under 80 bytes; a
// `% railmodal dofs:` list may be split over as many lines as it needs).
constexpr size_t kMaxLineLength = size_t(1) << 20;
// Each entry costs about 100 bytes while it is read and assembled (the entry and its line and
// column, the triplet and its mirror, the sparse matrix and the copy setFromTriplets makes):
// 2·10⁷ entries are about 2 GB, as much as the 10⁷-row limit's diagonal matrix twice over.
constexpr long long kMaxEntries = 20'000'000;
constexpr double kBytesPerEntry = 100.0;
// A DOF label names a body and a motion ("wagon3.bogie2.wheelset1.lateral" is 31 bytes).
constexpr size_t kMaxLabelLength = 256;

bool is_control(unsigned char b) { return (b < 0x20 && b != '\t') || b == 0x7f; }

// Reads lines, counting them, dropping a CR before the LF, and rejecting what is not text
// at the first offending byte, before reading the rest of its line (a 1 GB hole of NULs is
// refused after one byte, not read whole).
class Lines {
 public:
  Lines(std::istream& in, const std::string& file) : in_(in), file_(file) {}

  bool next(std::string* line) {
    line->clear();
    std::streambuf& buffer = *in_.rdbuf();
    int c = buffer.sbumpc();
    if (c == std::char_traits<char>::eof()) return false;
    if (number_ == std::numeric_limits<int>::max())
      fail(0, "the file has more than " + std::to_string(number_) + " lines: this is not a Matrix Market file");
    ++number_;
    for (; c != std::char_traits<char>::eof() && c != '\n'; c = buffer.sbumpc()) {
      const auto b = static_cast<unsigned char>(c);
      const int column = static_cast<int>(line->size()) + 1;
      if (is_control(b) && !(b == '\r' && buffer.sgetc() == '\n'))
        fail(column, "control character " + input::byte_name(b) + ": this is not a text file");
      if (b == '\r') continue;  // the CR of a CRLF: not part of the line, nor of its length
      if (line->size() == kMaxLineLength)
        fail(column,
             "the line is longer than " + std::to_string(kMaxLineLength) + " bytes: this is not a Matrix Market file");
      line->push_back(static_cast<char>(c));
    }
    if (const size_t bad = input::invalid_utf8_at(*line); bad != std::string::npos)
      fail(static_cast<int>(bad) + 1,
           "byte " + input::byte_name(static_cast<unsigned char>((*line)[bad])) + " is not UTF-8 text");
    return true;
  }
  int number() const { return number_; }
  [[noreturn]] void fail(int column, const std::string& message) const { fail_at(number_, column, message); }
  [[noreturn]] void fail_at(int line, int column, const std::string& message) const {
    throw InputError(file_, line, column, message);
  }

 private:
  std::istream& in_;
  const std::string& file_;
  int number_ = 0;
};

bool is_blank(std::string_view line) { return line.find_first_not_of(" \t") == std::string_view::npos; }
bool is_comment(std::string_view line) {
  const size_t first = line.find_first_not_of(" \t");
  return first != std::string_view::npos && line[first] == '%';
}

// A non-negative integer written in decimal digits only.
std::optional<long long> count_of(std::string_view text) {
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 0 || text[0] == '-') return std::nullopt;
  return value;
}

struct Header {
  bool coordinate = true;
  bool integer = false;
  bool symmetric = false;
};

Header parse_banner(const std::string& line, const Lines& lines) {
  const std::string how = std::string("; the first line must be the banner '") + kBanner + "'";
  const auto words = split(line);
  if (words.empty() || words[0].column != 1 || lower(words[0].text) != "%%matrixmarket")
    lines.fail(1, "not a Matrix Market file" + how);
  if (words.size() != 5)
    lines.fail(1, "the banner needs four words after %%MatrixMarket (matrix, coordinate or array, "
                  "real or integer, general or symmetric), found " + std::to_string(words.size() - 1));
  Header h;
  const std::string object = lower(words[1].text), format = lower(words[2].text);
  const std::string field = lower(words[3].text), symmetry = lower(words[4].text);
  if (object != "matrix")
    lines.fail(words[1].column, "object " + quoted(words[1].text) + " is not supported: only 'matrix'");
  if (format == "array") h.coordinate = false;
  else if (format != "coordinate")
    lines.fail(words[2].column, "unknown format " + quoted(words[2].text) + ": expected coordinate or array");
  if (field == "integer") h.integer = true;
  else if (field == "pattern" || field == "complex")
    lines.fail(words[3].column, "field '" + field + "' is not supported: mass, damping and stiffness "
                                "matrices need real values (real or integer)");
  else if (field != "real")
    lines.fail(words[3].column, "unknown field " + quoted(words[3].text) + ": expected real or integer");
  if (symmetry == "symmetric") h.symmetric = true;
  else if (symmetry == "hermitian" || symmetry == "skew-symmetric")
    lines.fail(words[4].column, "symmetry '" + symmetry + "' is not supported: expected general or symmetric");
  else if (symmetry != "general")
    lines.fail(words[4].column, "unknown symmetry " + quoted(words[4].text) + ": expected general or symmetric");
  return h;
}

double parse_value(const Token& t, bool integer, const Lines& lines) {
  std::string_view text = t.text;
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  if (integer) {
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
      lines.fail(t.column, quoted(t.text) + " is not an integer (the banner declares integer values)");
    return static_cast<double>(value);
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range)
    lines.fail(t.column, "value " + quoted(t.text) + " is outside the range of a double");
  if (error != std::errc() || end != text.data() + text.size())
    lines.fail(t.column, quoted(t.text) + " is not a number");
  if (!std::isfinite(value)) lines.fail(t.column, "value " + quoted(t.text) + " is not a finite number");
  // The same band as a quantity in a TOML file (table_reader.hpp): a subnormal mass gave an
  // eigensolver that "did not converge" instead of an input error.
  if (!input::within_magnitudes(value))
    lines.fail(t.column, "value " + quoted(t.text) + ": " + input::magnitude_complaint(value));
  return value;
}

// `% railmodal ...` comments naming degrees of freedom (docs/input.md).
struct DofNames {
  struct Name {
    std::string label;
    int line = 0, column = 0;
  };
  std::map<long long, Name> by_index;  // 1-based
  long long listed = 0;                // DOFs named by `dofs:` lists so far
  int list_line = 0, indexed_line = 0;

  void read(std::string_view comment, const Lines& lines) {
    const auto words = split(comment);
    // words[0] is "%" or "%railmodal"-like; accept "% railmodal" and "%railmodal".
    size_t k = 0;
    if (words.empty()) return;
    const size_t after = words[0].text.find_first_not_of('%');
    const std::string_view first = after == std::string_view::npos ? std::string_view() : words[0].text.substr(after);
    if (first.empty()) {
      if (words.size() < 2 || words[1].text != "railmodal") return;
      k = 2;
    } else {
      if (first != "railmodal") return;
      k = 1;
    }
    const int line = lines.number();
    const std::string forms = "expected '% railmodal dofs: LABEL ...' or '% railmodal dof INDEX LABEL'";
    if (k >= words.size()) lines.fail(words[k - 1].column, "empty railmodal comment: " + forms);
    const Token& keyword = words[k];
    if (keyword.text == "dofs:") {
      if (indexed_line) lines.fail(keyword.column, "a file names its DOFs either with 'railmodal dofs:' lists or "
                                                   "with 'railmodal dof INDEX LABEL' lines, not both");
      if (!list_line) list_line = line;
      for (size_t w = k + 1; w < words.size(); ++w) add(++listed, words[w], line, lines);
    } else if (keyword.text == "dof") {
      if (list_line) lines.fail(keyword.column, "a file names its DOFs either with 'railmodal dofs:' lists or "
                                                "with 'railmodal dof INDEX LABEL' lines, not both");
      if (words.size() != k + 3) lines.fail(keyword.column, "expected '% railmodal dof INDEX LABEL'");
      const auto index = count_of(words[k + 1].text);
      if (!index || *index == 0)
        lines.fail(words[k + 1].column, "DOF index " + quoted(words[k + 1].text) + " is not a positive integer");
      if (!indexed_line) indexed_line = line;
      add(*index, words[k + 2], line, lines);
    } else {
      lines.fail(keyword.column, "unknown railmodal comment " + quoted(keyword.text) + ": " + forms);
    }
  }

  void add(long long index, const Token& label, int line, const Lines& lines) {
    // Before the size line nothing else bounds them: at most one name per row railmodal reads,
    // each of a label's length, so that names cost at most about 3 GB (10⁷ of them, each in two
    // maps, about 300 bytes with its label) however long the file's lines.
    if (static_cast<long long>(by_index.size()) == kMaxRows)
      lines.fail(label.column, "more DOF names than the " + std::to_string(kMaxRows) + " rows railmodal reads");
    if (label.text.size() > kMaxLabelLength)
      lines.fail(label.column, "a DOF label of " + std::to_string(label.text.size()) + " bytes: labels are at most " +
                                   std::to_string(kMaxLabelLength) + " bytes");
    // A map from label to DOF: a 10⁵-DOF model names its DOFs in linear-logarithmic time.
    if (const auto twice = index_of.find(std::string(label.text)); twice != index_of.end())
      lines.fail(label.column, "DOF label " + quoted(label.text) + " is given twice (also DOF " +
                                   std::to_string(twice->second) + ", line " +
                                   std::to_string(by_index.at(twice->second).line) + ")");
    auto [it, inserted] = by_index.emplace(index, Name{std::string(label.text), line, label.column});
    if (!inserted)
      lines.fail(label.column, "DOF " + std::to_string(index) + " is already named '" + it->second.label +
                                   "' (line " + std::to_string(it->second.line) + ")");
    index_of.emplace(std::string(label.text), index);
  }
  std::map<std::string, long long> index_of;  // label → 1-based DOF

  // Once the size is known: every index in range, a list complete.
  std::vector<std::string> labels(long long n, const Lines& lines) const {
    if (by_index.empty()) return {};
    for (const auto& [i, name] : by_index)
      if (i > n)
        lines.fail_at(name.line, name.column, (list_line ? "the 'railmodal dofs:' comments name more DOFs than the "
                                                         : "DOF index " + std::to_string(i) + " exceeds the ") +
                                                  std::to_string(n) + " rows of the matrix");
    if (list_line && listed < n)
      lines.fail_at(list_line, 1, "the 'railmodal dofs:' comments name " + std::to_string(listed) +
                                      " DOFs but the matrix has " + std::to_string(n) + " rows");
    std::vector<std::string> out(static_cast<size_t>(n));
    for (const auto& [i, name] : by_index) out[static_cast<size_t>(i - 1)] = name.label;
    return out;
  }
};

struct Entry {
  int row = 0, col = 0;  // 0-based
  double value = 0.0;
  int line = 0, column = 0;
};

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The first entry in file order whose mirror differs beyond round-off (see the header).
void check_symmetric(const Eigen::SparseMatrix<double>& A, const std::vector<Entry>& entries, const Lines& lines) {
  double largest = 0.0;
  for (int k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) largest = std::max(largest, std::abs(it.value()));
  for (const Entry& e : entries) {
    if (e.row == e.col) continue;
    const double a = A.coeff(e.row, e.col), b = A.coeff(e.col, e.row);
    if (std::abs(a - b) <= 1e-10 * std::max(std::abs(a), std::abs(b)) + 1e-14 * largest) continue;
    const auto at = [](int i, int j) { return "(" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")"; };
    lines.fail_at(e.line, e.column,
                  "the matrix is not symmetric: entry " + at(e.row, e.col) + " is " + number_text(a) + " but " +
                      at(e.col, e.row) + " is " + number_text(b) +
                      "; mass and stiffness matrices must be symmetric (a 'general' file holds both "
                      "triangles; a file holding only the lower one must say 'symmetric')");
  }
}

// The next line that holds data, passing comments (which may name the DOFs) and blank lines,
// into *line; its tokens (views into *line), or none at the end of the file.
std::vector<Token> next_data_line(Lines& lines, DofNames& names, std::string* line) {
  while (lines.next(line)) {
    if (is_comment(*line)) {
      names.read(*line, lines);
      continue;
    }
    if (is_blank(*line)) continue;
    return split(*line);
  }
  return {};
}

std::string gigabytes(double bytes) {
  std::ostringstream s;
  s.precision(2);
  s << bytes / 1e9 << " GB";
  return s.str();
}

// The size line: n (square), and the number of entries (coordinate) or values (array) to come.
struct SizeLine {
  long long n = 0;
  long long expected = 0;
  std::string expected_text;  // "12 entries", or "21 values (a symmetric 6 × 6 array)"
  int line = 0;
  int last_column = 0;
};

SizeLine read_size_line(Lines& lines, DofNames& names, const Header& header) {
  std::string line;
  const std::vector<Token> size = next_data_line(lines, names, &line);
  const std::string size_form = header.coordinate ? "ROWS COLUMNS ENTRIES" : "ROWS COLUMNS";
  if (size.empty()) lines.fail(0, "the file ends before the size line (" + size_form + ")");
  SizeLine out;
  out.line = lines.number();
  out.last_column = size.back().column;
  if (size.size() != (header.coordinate ? 3u : 2u))
    lines.fail(size[0].column, "the size line of a " + std::string(header.coordinate ? "coordinate" : "array") +
                                   " file is '" + size_form + "', found " + std::to_string(size.size()) + " words");
  std::vector<long long> numbers;
  for (const Token& t : size) {
    const auto value = count_of(t.text);
    if (!value) lines.fail(t.column, "size " + quoted(t.text) + " is not a non-negative integer");
    numbers.push_back(*value);
  }
  const long long n = numbers[0];
  if (numbers[0] != numbers[1])
    lines.fail(size[0].column, "the matrix is " + std::to_string(numbers[0]) + " × " + std::to_string(numbers[1]) +
                                   ": mass, damping and stiffness matrices are square");
  if (n == 0) lines.fail(size[0].column, "the matrix is empty (0 × 0)");
  if (n > kMaxRows)
    lines.fail(size[0].column, "the matrix has " + std::to_string(n) + " rows, more than the " +
                                   std::to_string(kMaxRows) + " railmodal reads");
  out.n = n;
  // Array: column by column, the lower triangle only when symmetric.
  out.expected = header.coordinate ? numbers[2] : header.symmetric ? n * (n + 1) / 2 : n * n;
  if (out.expected > kMaxEntries)
    lines.fail(size[header.coordinate ? 2 : 0].column,
               "the size line declares " + std::to_string(out.expected) + (header.coordinate ? " entries" : " values") +
                   ", which would need about " + gigabytes(static_cast<double>(out.expected) * kBytesPerEntry) +
                   " to read; railmodal reads at most " + std::to_string(kMaxEntries) + " (about " +
                   gigabytes(static_cast<double>(kMaxEntries) * kBytesPerEntry) + ")");
  out.expected_text =
      header.coordinate ? std::to_string(out.expected) + " entries"
                        : std::to_string(out.expected) + " values (a " + (header.symmetric ? "symmetric " : "general ") +
                              std::to_string(n) + " × " + std::to_string(n) + " array)";
  return out;
}

// 'ROW COLUMN VALUE', 1-based, in the lower triangle when the file is symmetric.
void read_coordinate_entry(const std::vector<Token>& tokens, long long n, const Header& header, const Lines& lines,
                           Entry* e) {
  if (tokens.size() != 3)
    lines.fail(tokens[0].column, "an entry is 'ROW COLUMN VALUE', found " + std::to_string(tokens.size()) + " words");
  long long index[2];
  for (int k = 0; k < 2; ++k) {
    const auto v = count_of(tokens[k].text);
    if (!v) lines.fail(tokens[k].column, std::string(k == 0 ? "row" : "column") + " index " +
                                             quoted(tokens[k].text) + " is not a positive integer");
    if (*v < 1 || *v > n)
      lines.fail(tokens[k].column, std::string(k == 0 ? "row" : "column") + " index " + std::to_string(*v) +
                                       " is out of range 1.." + std::to_string(n));
    index[k] = *v - 1;
  }
  if (header.symmetric && index[0] < index[1])
    lines.fail(tokens[0].column, "entry (" + std::to_string(index[0] + 1) + ", " + std::to_string(index[1] + 1) +
                                     ") lies above the diagonal: a symmetric file stores the lower triangle "
                                     "(row ≥ column)");
  e->row = static_cast<int>(index[0]);
  e->col = static_cast<int>(index[1]);
  e->value = parse_value(tokens[2], header.integer, lines);
}

// The entries up to the end of the file: exactly as many as the size line declares.
std::vector<Entry> read_entries(Lines& lines, DofNames& names, const Header& header, const SizeLine& size) {
  std::vector<Entry> entries;
  entries.reserve(static_cast<size_t>(std::min<long long>(size.expected, 1 << 20)));
  long long array_row = 0, array_col = 0;
  std::string line;
  for (std::vector<Token> tokens; !(tokens = next_data_line(lines, names, &line)).empty();) {
    if (static_cast<long long>(entries.size()) == size.expected)
      lines.fail(tokens[0].column, "more entries than the " + size.expected_text + " the size line (line " +
                                       std::to_string(size.line) + ") declares");
    Entry e;
    e.line = lines.number();
    e.column = tokens[0].column;
    if (header.coordinate) {
      read_coordinate_entry(tokens, size.n, header, lines, &e);
    } else {  // one value per line, column by column
      if (tokens.size() != 1)
        lines.fail(tokens[1].column, "an array file holds one value per line, found " + std::to_string(tokens.size()));
      e.row = static_cast<int>(array_row);
      e.col = static_cast<int>(array_col);
      e.value = parse_value(tokens[0], header.integer, lines);
      if (++array_row == size.n) {
        ++array_col;
        array_row = header.symmetric ? array_col : 0;
      }
    }
    entries.push_back(e);
  }
  if (static_cast<long long>(entries.size()) < size.expected)
    lines.fail_at(size.line, size.last_column,
                  "the size line declares " + size.expected_text + " but the file ends after " +
                      std::to_string(entries.size()));
  return entries;
}

// Duplicates summed; a symmetric file's entries mirrored above the diagonal.
Eigen::SparseMatrix<double> sparse_matrix(const std::vector<Entry>& entries, long long n, bool symmetric) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(entries.size() * (symmetric ? 2 : 1));
  for (const Entry& e : entries) {
    triplets.emplace_back(e.row, e.col, e.value);
    if (symmetric && e.row != e.col) triplets.emplace_back(e.col, e.row, e.value);
  }
  Eigen::SparseMatrix<double> matrix(static_cast<int>(n), static_cast<int>(n));
  matrix.setFromTriplets(triplets.begin(), triplets.end());  // sums duplicates
  return matrix;
}

}  // namespace

MatrixMarketMatrix read_matrix_market(const std::string& path, bool require_symmetric) {
  std::ifstream in = input::open_input(path);
  Lines lines(in, path);
  std::string line;
  if (!lines.next(&line)) lines.fail(0, std::string("the file is empty; it must start with the banner '") + kBanner + "'");
  const Header header = parse_banner(line, lines);
  DofNames names;
  const SizeLine size = read_size_line(lines, names, header);
  const std::vector<Entry> entries = read_entries(lines, names, header, size);

  MatrixMarketMatrix out;
  out.symmetric_storage = header.symmetric;
  out.size_line = size.line;
  out.dof_labels = names.labels(size.n, lines);
  out.labels_line = names.list_line ? names.list_line : names.indexed_line;
  out.matrix = sparse_matrix(entries, size.n, header.symmetric);
  if (require_symmetric && !header.symmetric) check_symmetric(out.matrix, entries, lines);
  return out;
}

}  // namespace railmodal
