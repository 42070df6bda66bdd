// Tables, units and page style shared by the report writers.
#include "report/document_table.hpp"

#include <algorithm>
#include <string>

#include "railmodal/version.hpp"
#include "report/report_page.hpp"
#include "report/svg_chart.hpp"

namespace railmodal::report {
namespace {

// A number and its " %" stay on one line: a narrow numeric column would otherwise wrap the sign
// under its number ("12.34" / "%", the audit of 2026-11-27).
std::string unbroken_percent(std::string cell) {
  for (size_t at = cell.find(" %"); at != std::string::npos; at = cell.find(" %", at))
    cell.replace(at, 1, "&nbsp;");
  return cell;
}

}  // namespace

void write_markdown_table(std::ostream& out, const Table& t) {
  out << "|";
  for (const auto& h : t.headers) out << " " << h << " |";
  out << "\n|";
  for (size_t c = 0; c < t.headers.size(); ++c) out << (t.numeric[c] ? "---:|" : "---|");
  out << "\n";
  for (const auto& row : t.rows) {
    out << "|";
    for (const auto& cell : row) out << " " << cell << " |";
    out << "\n";
  }
  out << "\n";
}

void write_html_table(std::ostream& out, const Table& t) {
  out << "<table><tr>";
  for (const auto& h : t.headers) out << "<th>" << html_escape(h) << "</th>";
  out << "</tr>\n";
  for (const auto& row : t.rows) {
    out << "<tr>";
    for (size_t c = 0; c < row.size(); ++c)
      out << (t.numeric[c] ? "<td class=n>" + unbroken_percent(html_escape(row[c])) : "<td>" + html_escape(row[c]))
          << "</td>";
    out << "</tr>\n";
  }
  out << "</table>\n";
}

void write_text_table(std::ostream& out, const Table& t) {
  std::vector<size_t> width(t.headers.size());
  for (size_t c = 0; c < t.headers.size(); ++c) width[c] = width_of(t.headers[c]);
  for (const auto& row : t.rows)
    for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], width_of(row[c]));
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string text;
    for (size_t c = 0; c < cells.size(); ++c) {
      const std::string fill(width[c] - width_of(cells[c]), ' ');  // ≥ 0: the column is as wide as its widest cell
      text += "  " + (t.numeric[c] ? fill + cells[c] : cells[c] + fill);
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out << text << "\n";
  };
  line(t.headers);
  for (const auto& row : t.rows) line(row);
}

bool is_rotation(const LinearSystem& system, const std::string& label) {
  const int d = system.index_of(label);
  if (d < 0) return false;
  const Motion m = system.dofs[d].motion;
  return m == Motion::roll || m == Motion::pitch || m == Motion::yaw;
}

Unit unit_of(const LinearSystem& system, const std::string& label, ResponseQuantity q) {
  const bool rotation = is_rotation(system, label);
  switch (q) {
    case ResponseQuantity::displacement: return rotation ? Unit{1e3, "mrad"} : Unit{1e3, "mm"};
    case ResponseQuantity::velocity: return rotation ? Unit{1e3, "mrad/s"} : Unit{1e3, "mm/s"};
    case ResponseQuantity::acceleration: return rotation ? Unit{1.0, "rad/s²"} : Unit{1.0, "m/s²"};
  }
  return {1.0, ""};
}

void write_html_head(std::ostream& out, const std::string& title) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << html_escape(title)
      << "</title>\n<style>body{font-family:sans-serif;max-width:1200px;margin:24px auto;"
         "color:#222;line-height:1.4}table{border-collapse:collapse;margin:8px 0 16px}td,th{border:1px solid #ccc;"
         "padding:3px 8px;font-size:13px}th{background:#f2f2f2}td.n{text-align:right}h2{border-bottom:1px solid #ddd;"
         "margin-top:28px}.note{color:#555;font-size:13px}.bad{color:#b00}.ok{color:#070}footer{border-top:1px solid "
         "#ddd;margin-top:32px;padding-top:6px}</style></head><body>\n";
}

std::string provenance_line(const std::string& command, const Provenance& provenance) {
  std::string line = "railmodal " + std::string(version()) + " " + command;
  if (provenance.files.empty()) return line + "; input files not recorded.";
  for (size_t k = 0; k < provenance.files.size(); ++k)
    line += (k ? ", " : ", from ") + provenance.files[k].path +
            (provenance.files[k].digest.empty() ? " (not a regular file: not hashed)"
                                                : " (FNV-1a 64 " + provenance.files[k].digest + ")");
  return line + ".";
}

void write_html_footer(std::ostream& out, const std::string& command, const Provenance& provenance) {
  out << "<footer class=note>Written by " << html_escape(provenance_line(command, provenance))
      << "</footer>\n</body></html>\n";
}

}  // namespace railmodal::report
