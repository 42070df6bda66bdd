// The layout of the long reports' JSON (ride, linear hunting): one member of the outermost object
// a line, its value compact on that line, and last a long array with one element a line (a
// speed's spectra, a branch's eigenvalues), so that the file reads and diffs without one number
// a line and without one line for the whole document.
//
//   write_line_member(out, "title", [&](JsonWriter& j) { j.value(title); }, true);
//   write_line_member(out, "notes", [&](JsonWriter& j) { j.value(notes); });
//   write_last_line_array(out, "speeds", speeds, [&](JsonWriter& j, const Speed& s) { ... });
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "report/json_writer.hpp"

namespace railmodal::report {

/// `"key": value` on a line of its own in the outermost object (`first` opens the object);
/// write_value(JsonWriter&) writes the value, compact.
template <typename WriteValue>
void write_line_member(std::ostream& out, std::string_view key, WriteValue write_value, bool first = false) {
  std::string name;
  append_json_string(name, key);
  out << (first ? "{\n  " : ",\n  ") << name << ": ";
  JsonWriter j(out, -1);
  write_value(j);
}

/// The outermost object's last member: an array with each element compact on a line of its own,
/// written by write_element(JsonWriter&, element); closes the object.
template <typename Element, typename WriteElement>
void write_last_line_array(std::ostream& out, std::string_view key, const std::vector<Element>& elements,
                           WriteElement write_element) {
  std::string name;
  append_json_string(name, key);
  out << ",\n  " << name << ": [";
  for (size_t k = 0; k < elements.size(); ++k) {
    out << (k ? ",\n    " : "\n    ");
    JsonWriter j(out, -1);
    write_element(j, elements[k]);
  }
  out << (elements.empty() ? "]" : "\n  ]") << "\n}\n";
}

}  // namespace railmodal::report
