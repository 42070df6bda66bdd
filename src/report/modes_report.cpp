#include <algorithm>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "railmodal/report.hpp"
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
  s << std::fixed << std::setprecision(3) << (c.about == "roll" ? "roll, z = " : "pitch, x = ")
    << position << " m";
  return s.str();
}

// Quantities that do not exist for a mode are written as blanks (CSV, table) or null
// (JSON), never as inf or NaN.
std::string number(double value, int precision, bool present) {
  if (!present) return "";
  std::ostringstream s;
  s << std::setprecision(precision) << value;
  return s.str();
}

using report::csv_field;
using report::csv_heading;

// The unit of a mass-normalised shape's entry (φᵀMφ = 1): the modal coordinate is in √kg·m, so
// a translation's entry is in m per √kg·m and a rotation's in rad per √kg·m. A matrix model's
// units are its matrices' (unknown): "".
std::string shape_unit(const Dof& dof) {
  if (dof.body < 0) return "";
  const std::string unit = report::displacement_unit(dof.label);
  return unit == "rad" ? "rad/(sqrt(kg) m)" : unit == "m" ? "1/sqrt(kg)" : "";
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
      out << std::setw(34) << ("diverges, σ = " + number(m.divergence_rate, 4, true) + " 1/s");
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
  out << "\nmode shapes (mass-normalised; m and rad per √kg)\n";
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
  for (const auto& note : r.notes) out << "# note: " << note << "\n";  // absent for the book's wagons
  out << "index,name,kind," << csv_heading("frequency", "Hz") << "," << csv_heading("period", "s") << ","
      << csv_heading("omega", "rad/s") << "," << csv_heading("divergence_rate", "1/s") << ",centre_of_oscillation";
  for (const auto& d : r.dofs) out << "," << csv_field(csv_heading(d.label, shape_unit(d)));
  out << "\n";
  for (const auto& m : r.modes) {
    const bool osc = m.kind == ModeKind::oscillatory;
    out << m.index << "," << csv_field(m.name) << "," << to_string(m.kind) << ","
        << number(m.frequency_hz, 10, osc) << "," << number(m.period_s, 10, osc) << ","
        << number(m.omega_rad_s, 10, osc) << ","
        << number(m.divergence_rate, 10, m.kind == ModeKind::unstable) << ","
        << csv_field(centre_text(m));
    for (int i = 0; i < m.shape.size(); ++i) out << "," << number(m.shape(i), 10, true);
    out << "\n";
  }
}

void write_json(std::ostream& out, const std::string& title, const ModalResult& r) {
  using nlohmann::json;
  json doc;
  doc["vehicle"] = title;
  doc["dofs"] = json::array();
  for (const auto& d : r.dofs) doc["dofs"].push_back(d.label);
  doc["modes"] = json::array();
  for (const auto& m : r.modes) {
    const bool osc = m.kind == ModeKind::oscillatory;
    json j;
    j["index"] = m.index;
    j["name"] = m.name;
    j["kind"] = to_string(m.kind);
    j["repeated"] = m.repeated;
    j["stable"] = m.kind != ModeKind::unstable;
    j["eigenvalue"] = m.eigenvalue;
    j["frequency_hz"] = osc ? json(m.frequency_hz) : json(nullptr);
    j["period_s"] = osc ? json(m.period_s) : json(nullptr);
    j["omega_rad_s"] = osc ? json(m.omega_rad_s) : json(nullptr);
    j["divergence_rate_per_s"] = m.kind == ModeKind::unstable ? json(m.divergence_rate) : json(nullptr);
    if (m.centre) {
      json c;
      c["body"] = m.centre->body;
      c["about"] = m.centre->about;
      c[m.centre->about == "roll" ? "z_m" : "x_m"] = m.centre->at_infinity ? json(nullptr) : json(m.centre->position);
      j["centre_of_oscillation"] = c;
    } else {
      j["centre_of_oscillation"] = nullptr;
    }
    j["residual"] = m.residual;
    json shape = json::object();
    for (size_t i = 0; i < r.dofs.size(); ++i) shape[r.dofs[i].label] = m.shape(static_cast<int>(i));
    j["shape"] = shape;
    doc["modes"].push_back(j);
  }
  doc["condensed"] = r.condensed;
  doc["max_residual"] = r.max_residual;
  doc["orthonormality_error"] = r.orthonormality_error;
  json solver;
  solver["name"] = to_string(r.solver.solver);
  if (r.solver.solver == ModalSolver::arpack) {
    solver["shift"] = r.solver.shift;
    solver["factorisation"] = r.solver.factorisation;
    solver["requested"] = r.solver.requested;
    solver["subspace_size"] = r.solver.subspace_size;
    solver["restarts"] = r.solver.restarts;
    solver["operator_applications"] = r.solver.operator_applications;
    solver["runs"] = r.solver.runs;
    solver["count_checked"] = r.solver.count_checked;
  }
  doc["solver"] = solver;
  if (!r.notes.empty()) doc["notes"] = r.notes;  // absent for the book's wagons: their files stay as they were
  out << doc.dump(2) << "\n";
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
