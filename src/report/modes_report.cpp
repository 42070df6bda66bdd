#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "railmodal/report.hpp"
#include "report/csv_writer.hpp"
#include "report/json_writer.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"

namespace railmodal {

namespace {

std::string centre_text(const Mode& mode) {
  if (!mode.centre) return "";
  const auto& c = *mode.centre;
  if (c.at_infinity) return c.about + ": none (translation)";
  std::ostringstream s;
  // Round-off must not print as "-0.000".
  const double position = std::abs(c.position) < 5e-4 ? 0.0 : c.position;
  // With its datum (the vehicle frame, docs/input.md): a roll centre's z is no height above the
  // body's reference point nor above rail, and reads as either without it.
  s << std::fixed << std::setprecision(3) << (c.about == "roll" ? "roll, z = " : "pitch, x = ")
    << position << (c.about == "roll" ? " m from the axle plane" : " m in the vehicle frame");
  return s.str();
}

using report::csv_heading;

// The unit of a mass-normalised shape's entry (φᵀMφ = 1): the modal coordinate is in √kg·m, so
// a translation's entry is in m per √kg·m and a rotation's in rad per √kg·m. A matrix model's
// units are its matrices' (unknown): "".
std::string shape_unit(const Dof& dof) {
  if (dof.body < 0) return "";
  const std::string unit = report::displacement_unit(dof.label);
  return unit == "rad" ? "rad/(sqrt(kg)·m)" : unit == "m" ? "1/sqrt(kg)" : "";
}

// One line on how ARPACK found the modes (nothing for the dense solver, which finds all).
std::string solver_line(const ModalResult& r) {
  const SolverSummary& s = r.solver;
  if (s.solver != ModalSolver::arpack) return "";
  std::ostringstream line;
  line << "solver: ARPACK shift-invert, σ = " << std::setprecision(3) << s.shift << " 1/s² (" << s.factorisation
       << " of K − σM), " << r.modes.size() << " lowest modes, ncv " << s.subspace_size << ", "
       << s.operator_applications << " solves" << (s.count_checked ? ", count checked by inertia" : "") << "\n";
  return line.str();
}

// A repeated mode is marked `*` unless its name already says so: "bogies pitch (repeated)".
std::string marked(const Mode& m) {
  const std::string says = "(repeated)";
  const bool named =
      m.name.size() >= says.size() && m.name.compare(m.name.size() - says.size(), says.size(), says) == 0;
  return m.repeated && !named ? m.name + " *" : m.name;
}

void write_table(std::ostream& out, const std::string& title, const ModalResult& r) {
  out << "railmodal modes: " << title << "\n";
  out << "degrees of freedom: " << r.dofs.size();
  if (!r.condensed.empty()) {
    out << " (massless, condensed statically:";
    for (const auto& c : r.condensed) out << " " << c;
    out << ")";
  }
  out << "\n" << solver_line(r) << "\n";
  for (const auto& note : r.notes) out << "note: " << note << "\n";
  out << std::left << std::setw(4) << "#" << std::setw(34) << "mode" << std::right << std::setw(11)
      << "f [Hz]" << std::setw(11) << "T [s]" << std::setw(12) << "ω [rad/s]" << "  "
      << "centre of oscillation\n";
  for (const auto& m : r.modes) {
    out << report::left_cell(std::to_string(m.index), 4) << report::left_cell(marked(m), 34) << std::right;
    if (m.kind == ModeKind::oscillatory) {
      out << report::right_cell(report::fixed(m.frequency_hz, 4), 11)
          << report::right_cell(report::fixed(m.period_s, 4), 11)
          << report::right_cell(report::fixed(m.omega_rad_s, 3), 12);
    } else if (m.kind == ModeKind::unstable) {
      out << std::setw(34) << ("diverges, σ = " + report::significant(m.divergence_rate, 4) + " 1/s");
    } else {
      out << std::setw(34) << "rigid-body (λ = 0)";
    }
    out << "  " << centre_text(m) << "\n";
  }
  for (const auto& m : r.modes)
    if (m.repeated) {
      out << "\n* or (repeated): repeated frequency: these modes span a shared subspace; any\n"
             "  combination of their shapes is an equally valid mode shape, so none has a centre\n"
             "  of oscillation.\n";
      break;
    }
  // The units the CSV heads its columns with (shape_unit); a matrix model's are its matrices'.
  const bool vehicle = std::any_of(r.dofs.begin(), r.dofs.end(), [](const Dof& d) { return d.body >= 0; });
  out << (vehicle ? "\nmode shapes (mass-normalised: translations in 1/sqrt(kg), rotations in rad/(sqrt(kg)·m))\n"
                  : "\nmode shapes (mass-normalised; in the units of the matrices)\n");
  // The DOF column: 18 wide, wider where a label needs it (bogie1.longitudinal is 19), with
  // one space before the first shape column.
  size_t dof_width = 18;
  for (const auto& d : r.dofs) dof_width = std::max(dof_width, d.label.size() + 1);
  const int label_width = static_cast<int>(dof_width);
  out << std::left << std::setw(label_width) << "dof" << std::right;
  for (const auto& m : r.modes) out << std::setw(11) << m.index;
  out << "\n";
  // Entries at round-off level of the mode's largest read as exact zeros (JSON and CSV keep the
  // raw values). The largest once per mode: per entry it made the table quadratic in the DOFs.
  std::vector<double> round_off;
  for (const auto& m : r.modes) round_off.push_back(1e-12 * m.shape.cwiseAbs().maxCoeff());
  for (size_t i = 0; i < r.dofs.size(); ++i) {
    out << report::left_cell(r.dofs[i].label, dof_width) << std::right;
    for (size_t k = 0; k < r.modes.size(); ++k) {
      const double v = r.modes[k].shape(static_cast<int>(i));
      if (std::abs(v) <= round_off[k])
        out << std::setw(11) << "0";
      else
        out << std::setw(11) << std::scientific << std::setprecision(2) << v;
    }
    out << "\n";
  }
  out << std::defaultfloat << "\nchecks: max relative residual " << std::setprecision(2) << r.max_residual
      << ", max |ΦᵀMΦ − I| " << r.orthonormality_error << "\n";
  for (const Check& c : r.solver.checks)
    if (!c.passed)
      out << "warning: check failed: " << c.name << " " << std::setprecision(2) << c.value << ", limit " << c.limit
          << " (docs/accuracy.md)\n";
}

void write_csv(std::ostream& out, const ModalResult& r) {
  report::CsvWriter csv(out);
  for (const auto& note : r.notes) csv.line("# note: " + note);  // absent for the book's wagons
  csv.field("index").field("name").field("kind").field(csv_heading("frequency", "Hz"))
      .field(csv_heading("period", "s")).field(csv_heading("omega", "rad/s"))
      .field(csv_heading("divergence_rate", "1/s")).field("centre_of_oscillation");
  for (const auto& d : r.dofs) csv.field(csv_heading(d.label, shape_unit(d)));
  csv.end_row();
  // A quantity a mode does not have is a blank field.
  const auto optional = [&csv](double value, bool present) -> report::CsvWriter& {
    return present ? csv.field(value) : csv.blank();
  };
  for (const auto& m : r.modes) {
    const bool osc = m.kind == ModeKind::oscillatory;
    csv.field(m.index).field(m.name).field(to_string(m.kind));
    optional(m.frequency_hz, osc);
    optional(m.period_s, osc);
    optional(m.omega_rad_s, osc);
    optional(m.divergence_rate, m.kind == ModeKind::unstable);
    csv.field(centre_text(m));
    for (int i = 0; i < m.shape.size(); ++i) csv.field(m.shape(i));
    csv.end_row();
  }
}

std::vector<std::string> dof_labels(const std::vector<Dof>& dofs) {
  std::vector<std::string> labels;
  for (const Dof& d : dofs) labels.push_back(d.label);
  return labels;
}

// Members in alphabetical order, as the files had them (json_writer.hpp).
void write_mode(report::JsonWriter& j, const ModalResult& r, const Mode& m, const std::vector<size_t>& order) {
  const bool osc = m.kind == ModeKind::oscillatory;
  const std::optional<double> none;
  j.begin_object();
  j.key("centre_of_oscillation");
  if (m.centre) {
    j.begin_object();
    j.member("about", m.centre->about).member("body", m.centre->body);
    j.key(m.centre->about == "roll" ? "z_m" : "x_m");
    j.value(m.centre->at_infinity ? none : std::optional<double>(m.centre->position));
    j.end_object();
  } else {
    j.value(nullptr);
  }
  j.member("divergence_rate_per_s", m.kind == ModeKind::unstable ? std::optional<double>(m.divergence_rate) : none);
  j.member("eigenvalue", m.eigenvalue);
  j.member("frequency_hz", osc ? std::optional<double>(m.frequency_hz) : none);
  j.member("index", m.index).member("kind", to_string(m.kind)).member("name", m.name);
  j.member("omega_rad_s", osc ? std::optional<double>(m.omega_rad_s) : none);
  j.member("period_s", osc ? std::optional<double>(m.period_s) : none);
  j.member("repeated", m.repeated).member("residual", m.residual);
  j.key("shape").begin_object();
  for (size_t i : order) j.member(r.dofs[i].label, m.shape(static_cast<int>(i)));
  j.end_object();
  j.member("stable", m.kind != ModeKind::unstable);
  j.end_object();
}

void write_json(std::ostream& out, const std::string& title, const ModalResult& r) {
  report::JsonWriter j(out);
  j.begin_object();
  j.member("condensed", r.condensed);
  j.key("dofs").begin_array();
  for (const auto& d : r.dofs) j.value(d.label);
  j.end_array();
  j.member("max_residual", r.max_residual);
  const std::vector<size_t> order = report::member_order(dof_labels(r.dofs));  // the shapes' members
  j.key("modes").begin_array();
  for (const auto& m : r.modes) write_mode(j, r, m, order);
  j.end_array();
  if (!r.notes.empty()) j.member("notes", r.notes);  // absent for the book's wagons: their files stay as they were
  j.member("orthonormality_error", r.orthonormality_error);
  j.key("solver").begin_object();
  const SolverSummary& s = r.solver;
  if (s.solver == ModalSolver::arpack) {
    j.member("count_checked", s.count_checked).member("factorisation", s.factorisation);
    j.member("name", to_string(s.solver));
    j.member("operator_applications", s.operator_applications).member("requested", s.requested);
    j.member("restarts", s.restarts).member("runs", s.runs).member("shift", s.shift);
    j.member("subspace_size", s.subspace_size);
  } else {
    j.member("name", to_string(s.solver));
  }
  j.end_object();
  j.member("vehicle", title);
  j.end_object();
}

}  // namespace

void write_modes(std::ostream& out, const LinearSystem& system, const ModalResult& result,
                 OutputFormat format) {
  write_modes(out, system.vehicle.name, result, format);
}

void write_modes(std::ostream& out, const std::string& title, const ModalResult& result, OutputFormat format) {
  switch (format) {
    case OutputFormat::table: write_table(out, title, result); break;
    case OutputFormat::csv: write_csv(out, result); break;
    case OutputFormat::json: write_json(out, title, result); break;
    default: throw std::invalid_argument(report::unwritten_format("write_modes", "table, csv or json", format));
  }
}

}  // namespace railmodal
