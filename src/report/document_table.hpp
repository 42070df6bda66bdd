// Pieces shared by the Markdown and HTML reports (critical speeds, design comparisons): a
// table built once and written either way, the engineering unit of an output, the page style.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/response.hpp"

namespace railmodal::report {

struct Table {
  std::vector<std::string> headers;
  std::vector<bool> numeric;  ///< right-aligned columns
  std::vector<std::vector<std::string>> rows;
};

void write_markdown_table(std::ostream& out, const Table& table);
void write_html_table(std::ostream& out, const Table& table);
/// The plain-text table of the text reports (linear and nonlinear hunting): each column as
/// wide as its widest cell in characters (report::width_of), two spaces before every cell,
/// numbers right-aligned, no trailing spaces.
void write_text_table(std::ostream& out, const Table& table);

/// Engineering units for one output: mm and mrad for displacements, m/s² for accelerations.
struct Unit {
  double scale;  ///< from SI
  std::string name;
};
Unit unit_of(const LinearSystem& system, const std::string& label, ResponseQuantity quantity);
/// Whether the DOF labelled `label` is a roll, pitch or yaw.
bool is_rotation(const LinearSystem& system, const std::string& label);

/// `<!DOCTYPE html>` up to the opening <body>: the one style every report page shares.
void write_html_head(std::ostream& out, const std::string& title);

/// What made the page, in one line: "railmodal 0.1.0 critical-speed, from data/scenes/x.toml
/// (FNV-1a 64 0123456789abcdef), ..." (or that the inputs were not recorded); a file with no
/// digest "(not a regular file: not hashed)".
std::string provenance_line(const std::string& command, const Provenance& provenance);
/// The page's footer (provenance_line) and its closing tags.
void write_html_footer(std::ostream& out, const std::string& command, const Provenance& provenance);

}  // namespace railmodal::report
