// Damped modes for people (table) and programs (CSV, JSON). Quantities a mode does not have
// (no damped frequency when overdamped, no ζ when divergent) are blank or null, never NaN.
#include <iomanip>
#include <optional>
#include <stdexcept>

#include "railmodal/report.hpp"
#include "report/csv_writer.hpp"
#include "report/json_writer.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"

namespace railmodal {
namespace {

// The undamped mode's frequency, when it oscillates.
std::optional<double> undamped_frequency(const DampedModalResult& r, const DampedMode& m) {
  if (m.undamped_mode <= 0) return std::nullopt;
  const Mode& u = r.undamped.modes[m.undamped_mode - 1];
  if (u.kind != ModeKind::oscillatory) return std::nullopt;
  return u.frequency_hz;
}

std::string remark(const DampedMode& m) {
  const std::string rate = report::significant(std::abs(m.decay_rate), 4) + " 1/s";
  switch (m.kind) {
    case DampedModeKind::underdamped: return m.stable ? "" : "grows at " + rate + " (ζ < 0)";
    case DampedModeKind::critical: return "critically damped, decays at " + rate;
    case DampedModeKind::overdamped:
      return m.stable ? "overdamped, slowest part decays at " + rate : "grows at " + rate + " (ζ < −1)";
    case DampedModeKind::divergent: return "diverges at σ = " + rate;
    case DampedModeKind::first_order:
      return m.stable ? "first-order, τ = " + report::significant(1.0 / m.decay_rate, 4) + " s" : "grows at " + rate;
    case DampedModeKind::rigid_body:
      return m.decay_rate > 0.0 ? "rigid-body (λ = 0), velocity decays at " + rate : "rigid-body (λ = 0)";
  }
  return "";
}

std::string fixed_or_blank(const std::optional<double>& value, int decimals) {
  return value ? report::fixed(*value, decimals) : "";
}

void write_table(std::ostream& out, const LinearSystem& system, const DampedModalResult& r) {
  out << "railmodal modes --damped: " << system.vehicle.name << "\n";
  out << "degrees of freedom: " << r.dofs.size();
  if (!r.condensed.empty()) {
    out << " (massless, condensed statically:";
    for (const auto& c : r.condensed) out << " " << c;
    out << ")";
  }
  if (!r.first_order.empty()) {
    out << " (massless with dampers, first-order:";
    for (const auto& c : r.first_order) out << " " << c;
    out << ")";
  }
  out << "\n";
  for (const auto& note : r.notes) out << "note: " << note << "\n";  // none for the book's wagons
  out << "\n";
  out << std::left << std::setw(4) << "#" << std::setw(34) << "mode" << std::right << std::setw(10) << "f_d [Hz]"
      << std::setw(10) << "ζ" /* 2 bytes, 1 column */ << std::setw(10) << "f_n [Hz]" << std::setw(10) << "f_0 [Hz]" << "  " << std::left
      << std::setw(10) << "stability" << "remark\n";
  for (const auto& m : r.modes) {
    out << report::left_cell(std::to_string(m.index), 4) << report::left_cell(m.name, 34)
        << report::right_cell(fixed_or_blank(m.damped_frequency_hz, 4), 10)
        << report::right_cell(fixed_or_blank(m.damping_ratio, 4), 9)
        << report::right_cell(fixed_or_blank(m.natural_frequency_hz, 4), 10)
        << report::right_cell(fixed_or_blank(undamped_frequency(r, m), 4), 10) << "  ";
    const std::string note = remark(m);
    if (note.empty())
      out << (m.stable ? "stable" : "UNSTABLE") << "\n";
    else
      out << std::left << std::setw(10) << (m.stable ? "stable" : "UNSTABLE") << note << "\n";
  }
  out << "\nf_d = |Im λ|/2π, ζ = −Re λ/|λ|, f_n = |λ|/2π (√(λ₁λ₂)/2π for a real pair), f_0: the undamped\n"
         "mode it comes from (C ignored). Complex mode shapes: --format json.\n";
  out << std::defaultfloat << "\nchecks: max relative residual ‖(λ²M + λC + K)φ‖ " << std::setprecision(2)
      << r.max_residual << "; " << (r.stable ? "stable" : "UNSTABLE") << "\n";
}

void write_csv(std::ostream& out, const DampedModalResult& r) {
  using report::csv_heading;
  report::CsvWriter csv(out);
  for (const auto& note : r.notes) csv.line("# note: " + note);
  csv.field("index").field("name").field("kind").field("stable").field(csv_heading("damped_frequency", "Hz"));
  csv.field("damping_ratio").field(csv_heading("natural_frequency", "Hz")).field("undamped_mode");
  csv.field(csv_heading("undamped_frequency", "Hz")).field(csv_heading("decay_rate", "1/s"));
  for (const char* part : {"eigenvalue1_re", "eigenvalue1_im", "eigenvalue2_re", "eigenvalue2_im"})
    csv.field(csv_heading(part, "1/s"));  // λ = −σ ± iω_d
  csv.field("residual").end_row();
  // A quantity the mode does not have is a blank field.
  const auto optional = [&csv](const std::optional<double>& value) -> report::CsvWriter& {
    return value ? csv.field(*value) : csv.blank();
  };
  for (const auto& m : r.modes) {
    csv.field(m.index).field(m.name).field(to_string(m.kind)).field(m.stable);
    optional(m.damped_frequency_hz);
    optional(m.damping_ratio);
    optional(m.natural_frequency_hz);
    m.undamped_mode > 0 ? csv.field(m.undamped_mode) : csv.blank();
    optional(undamped_frequency(r, m));
    csv.field(m.decay_rate);
    for (size_t k = 0; k < 2; ++k) {
      if (k < m.eigenvalues.size())
        csv.field(m.eigenvalues[k].real()).field(m.eigenvalues[k].imag());
      else
        csv.blank().blank();
    }
    csv.field(m.residual).end_row();
  }
}

// Members in alphabetical order, as the files had them (json_writer.hpp).
void write_mode(report::JsonWriter& j, const DampedModalResult& r, const DampedMode& m,
                const std::vector<size_t>& order) {
  j.begin_object();
  j.member("damped_frequency_hz", m.damped_frequency_hz).member("damping_ratio", m.damping_ratio);
  j.member("decay_rate_per_s", m.decay_rate);
  j.key("eigenvalues").begin_array();
  for (const auto& l : m.eigenvalues) j.begin_array().value(l.real()).value(l.imag()).end_array();
  j.end_array();
  j.member("index", m.index).member("kind", to_string(m.kind)).member("name", m.name);
  j.member("natural_frequency_hz", m.natural_frequency_hz).member("residual", m.residual);
  j.key("shape").begin_object();
  for (size_t i : order) {
    const auto v = m.shape(static_cast<int>(i));
    j.key(r.dofs[i].label).begin_array().value(v.real()).value(v.imag()).end_array();
  }
  j.end_object();
  j.member("stable", m.stable).member("undamped_frequency_hz", undamped_frequency(r, m));
  j.key("undamped_mode");
  m.undamped_mode > 0 ? j.value(m.undamped_mode) : j.value(nullptr);
  j.end_object();
}

void write_json(std::ostream& out, const LinearSystem& system, const DampedModalResult& r) {
  report::JsonWriter j(out);
  std::vector<std::string> labels;
  for (const auto& d : r.dofs) labels.push_back(d.label);
  const std::vector<size_t> order = report::member_order(labels);  // the shapes' members
  j.begin_object();
  j.member("condensed", r.condensed).member("dofs", labels).member("first_order", r.first_order);
  j.member("max_residual", r.max_residual);
  j.key("modes").begin_array();
  for (const auto& m : r.modes) write_mode(j, r, m, order);
  j.end_array();
  if (!r.notes.empty()) j.member("notes", r.notes);  // absent for the book's wagons
  j.member("stable", r.stable).member("vehicle", system.vehicle.name);
  j.end_object();
}

}  // namespace

void write_damped_modes(std::ostream& out, const LinearSystem& system, const DampedModalResult& result,
                        OutputFormat format) {
  switch (format) {
    case OutputFormat::table: write_table(out, system, result); break;
    case OutputFormat::csv: write_csv(out, result); break;
    case OutputFormat::json: write_json(out, system, result); break;
    default: throw std::invalid_argument(report::unwritten_format("write_damped_modes", "table, csv or json", format));
  }
}

}  // namespace railmodal
