// Damped modes for people (table) and programs (CSV, JSON). Quantities a mode does not have
// (no damped frequency when overdamped, no ζ when divergent) are blank or null, never NaN.
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "railmodal/report.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"

namespace railmodal {
namespace {

using report::csv_field;

std::string optional_number(const std::optional<double>& value, int precision) {
  if (!value) return "";
  std::ostringstream s;
  s << std::setprecision(precision) << *value;
  return s.str();
}

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
  for (const auto& note : r.undamped.notes) out << "note: " << note << "\n";  // none for the book's wagons
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
  for (const auto& note : r.undamped.notes) out << "# note: " << note << "\n";
  out << "index,name,kind,stable," << csv_heading("damped_frequency", "Hz") << ",damping_ratio,"
      << csv_heading("natural_frequency", "Hz") << ",undamped_mode," << csv_heading("undamped_frequency", "Hz") << ","
      << csv_heading("decay_rate", "1/s");
  for (const char* part : {"eigenvalue1_re", "eigenvalue1_im", "eigenvalue2_re", "eigenvalue2_im"})
    out << "," << csv_heading(part, "1/s");  // λ = −σ ± iω_d
  out << ",residual\n";
  for (const auto& m : r.modes) {
    out << m.index << "," << csv_field(m.name) << "," << to_string(m.kind) << "," << (m.stable ? "true" : "false")
        << "," << optional_number(m.damped_frequency_hz, 10) << "," << optional_number(m.damping_ratio, 10) << ","
        << optional_number(m.natural_frequency_hz, 10) << ","
        << (m.undamped_mode > 0 ? std::to_string(m.undamped_mode) : "") << ","
        << optional_number(undamped_frequency(r, m), 10) << "," << optional_number(m.decay_rate, 10);
    for (size_t k = 0; k < 2; ++k) {
      if (k < m.eigenvalues.size())
        out << "," << optional_number(m.eigenvalues[k].real(), 12) << "," << optional_number(m.eigenvalues[k].imag(), 12);
      else
        out << ",,";
    }
    out << "," << optional_number(m.residual, 3) << "\n";
  }
}

void write_json(std::ostream& out, const LinearSystem& system, const DampedModalResult& r) {
  using nlohmann::json;
  auto or_null = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  json doc;
  doc["vehicle"] = system.vehicle.name;
  doc["dofs"] = json::array();
  for (const auto& d : r.dofs) doc["dofs"].push_back(d.label);
  doc["modes"] = json::array();
  for (const auto& m : r.modes) {
    json j;
    j["index"] = m.index;
    j["name"] = m.name;
    j["kind"] = to_string(m.kind);
    j["stable"] = m.stable;
    j["eigenvalues"] = json::array();
    for (const auto& l : m.eigenvalues) j["eigenvalues"].push_back({l.real(), l.imag()});
    j["damped_frequency_hz"] = or_null(m.damped_frequency_hz);
    j["damping_ratio"] = or_null(m.damping_ratio);
    j["natural_frequency_hz"] = or_null(m.natural_frequency_hz);
    j["undamped_mode"] = m.undamped_mode > 0 ? json(m.undamped_mode) : json(nullptr);
    j["undamped_frequency_hz"] = or_null(undamped_frequency(r, m));
    j["decay_rate_per_s"] = m.decay_rate;
    j["residual"] = m.residual;
    json shape = json::object();
    for (size_t i = 0; i < r.dofs.size(); ++i) {
      const auto v = m.shape(static_cast<int>(i));
      shape[r.dofs[i].label] = {v.real(), v.imag()};
    }
    j["shape"] = shape;
    doc["modes"].push_back(j);
  }
  doc["condensed"] = r.condensed;
  doc["first_order"] = r.first_order;
  doc["stable"] = r.stable;
  doc["max_residual"] = r.max_residual;
  if (!r.undamped.notes.empty()) doc["notes"] = r.undamped.notes;  // absent for the book's wagons
  out << doc.dump(2) << "\n";
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
