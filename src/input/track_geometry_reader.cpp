// Measured track geometry from a CSV file (ride_simulation.hpp, load_track_geometry): a header
// naming each column with its unit, rows at a constant distance step. Every error names the
// file, the line, the column (its character position and its header name).
#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "input/input_file.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/ride_simulation.hpp"

namespace railmodal {
namespace {

// A geometry file of a few hundred kilometres at 0.25 m with four columns is some tens of
// megabytes; the limit keeps a wrong file (or an endless pipe) from filling memory.
constexpr size_t kMaxGeometryFileSize = size_t{1} << 30;

// Samples may be written rounded: a distance may miss its place on the constant step by this
// fraction of the step (a thousandth moves an interpolated sample by a thousandth of the
// change over one step).
constexpr double kStepTolerance = 1e-3;

enum class Column { distance, vertical_level, alignment, cross_level };

struct Field {
  std::string text;
  int column = 1;  // 1-based character position of the field in its line
};

struct HeaderColumn {
  Column kind = Column::distance;
  double scale = 1.0;  // SI metres per unit written
  std::string name;    // as written, for messages
};

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<Field> split(const std::string& line) {
  std::vector<Field> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    const std::string raw = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const size_t lead = raw.find_first_not_of(" \t");
    fields.push_back({trim(raw), static_cast<int>(start + (lead == std::string::npos ? 0 : lead)) + 1});
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

HeaderColumn header_column(const std::string& file, int line, const Field& field) {
  const size_t open = field.text.find('['), close = field.text.find(']');
  if (open == std::string::npos || close == std::string::npos || close < open || close + 1 != field.text.size())
    throw InputError(file, line, field.column,
                     "column '" + field.text + "': a header names each column with its unit in brackets, "
                     "such as 'vertical level [mm]'");
  HeaderColumn out;
  out.name = field.text;
  const std::string name = trim(field.text.substr(0, open)), unit = trim(field.text.substr(open + 1, close - open - 1));
  if (name == "distance") out.kind = Column::distance;
  // The scene's words (vertical_level, cross_level), or the spellings before 2026-11-27.
  else if (name == "vertical_level" || name == "vertical level") out.kind = Column::vertical_level;
  else if (name == "alignment") out.kind = Column::alignment;
  else if (name == "cross_level" || name == "cross-level") out.kind = Column::cross_level;
  else
    throw InputError(file, line, field.column,
                     "column '" + field.text + "': unknown column '" + name +
                         "'; expected distance, vertical_level, alignment or cross_level");
  if (unit == "m") out.scale = 1.0;
  else if (unit == "mm") out.scale = 1e-3;
  else
    throw InputError(file, line, field.column,
                     "column '" + field.text + "': unit '" + unit + "' is not a length in m or mm");
  return out;
}

double number(const std::string& file, int line, const Field& field, const HeaderColumn& column) {
  double value = 0.0;
  const char* begin = field.text.data();
  const char* end = begin + field.text.size();
  if (!field.text.empty() && *begin == '+') ++begin;  // from_chars takes no plus sign
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (field.text.empty() || error != std::errc() || stop != end)
    throw InputError(file, line, field.column, "column '" + column.name + "': '" + field.text + "' is not a number");
  if (!std::isfinite(value))
    throw InputError(file, line, field.column, "column '" + column.name + "': the value must be finite");
  return value * column.scale;
}

}  // namespace

TrackGeometry load_track_geometry(const std::string& path) {
  const std::string text =
      input::read_input_text(path, kMaxGeometryFileSize, "track geometry (1 GiB; a longer record can be split)");
  std::istringstream lines(text);
  std::vector<HeaderColumn> header;
  std::vector<std::vector<double>> columns;
  std::vector<int> row_lines, distance_columns;  // where each row's distance is written
  std::string line;
  int line_number = 0, header_line = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    if (trim(line).empty() || trim(line)[0] == '#') continue;  // blank lines and comments
    const std::vector<Field> fields = split(line);
    if (header.empty()) {
      header_line = line_number;
      for (const Field& field : fields) {
        header.push_back(header_column(path, line_number, field));
        for (size_t j = 0; j + 1 < header.size(); ++j)
          if (header[j].kind == header.back().kind)
            throw InputError(path, line_number, field.column, "column '" + field.text + "': named twice");
      }
      columns.resize(header.size());
      continue;
    }
    if (fields.size() != header.size())
      throw InputError(path, line_number, fields.back().column,
                       "the row has " + std::to_string(fields.size()) + " fields; the header names " +
                           std::to_string(header.size()) + " columns");
    for (size_t j = 0; j < fields.size(); ++j) {
      columns[j].push_back(number(path, line_number, fields[j], header[j]));
      if (header[j].kind == Column::distance) distance_columns.push_back(fields[j].column);
    }
    row_lines.push_back(line_number);
  }
  if (header.empty()) throw InputError(path, 0, 0, "no header row: expected columns such as 'distance [m], vertical level [mm]'");
  int distance = -1;
  for (size_t j = 0; j < header.size(); ++j)
    if (header[j].kind == Column::distance) distance = static_cast<int>(j);
  if (distance < 0) throw InputError(path, header_line, 1, "no column 'distance [m]' in the header");
  if (header.size() < 2)
    throw InputError(path, header_line, 1, "no geometry column: expected vertical level, alignment or cross-level");
  const std::vector<double>& d = columns[distance];
  if (d.size() < 2) throw InputError(path, header_line, 1, "at least two rows of samples are needed for a step");

  // The step from the whole record (the first and last distances), each row then checked
  // against its place on it: a rounded distance does not throw the step off.
  const double step = (d.back() - d.front()) / static_cast<double>(d.size() - 1);
  for (size_t i = 1; i < d.size(); ++i)
    if (!(d[i] > d[i - 1]))
      throw InputError(path, row_lines[i], distance_columns[i],
                       "column '" + header[distance].name + "': distances must increase");
  for (size_t i = 0; i < d.size(); ++i) {
    const double expected = d.front() + static_cast<double>(i) * step;
    if (std::abs(d[i] - expected) > kStepTolerance * step) {
      std::ostringstream why;
      why << "column '" << header[distance].name << "': the distance " << d[i] << " m is off the constant step "
          << step << " m (expected " << expected << " m)";
      throw InputError(path, row_lines[i], distance_columns[i], why.str());
    }
  }

  TrackGeometry geometry;
  geometry.step = step;
  geometry.periodic = false;
  geometry.source = path;
  for (size_t j = 0; j < header.size(); ++j) {
    const Eigen::VectorXd samples = Eigen::Map<const Eigen::VectorXd>(columns[j].data(), columns[j].size());
    if (header[j].kind == Column::vertical_level) geometry.vertical_level = samples;
    if (header[j].kind == Column::alignment) geometry.alignment = samples;
    if (header[j].kind == Column::cross_level) geometry.cross_level = samples;
  }
  return geometry;
}

}  // namespace railmodal
