// A scene's simulation for programs: time histories as CSV or JSON, spectra as CSV.
#include "railmodal/simulation_report.hpp"

#include <iomanip>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "report/unwritten_format.hpp"

namespace railmodal {
namespace {

void write_history_json(std::ostream& out, const TimeHistory& h, const Scene& scene, const Vehicle& vehicle) {
  nlohmann::json j;
  j["scene"] = scene.name;
  j["time_s"] = std::vector<double>(h.time.data(), h.time.data() + h.time.size());
  j["displacement"] = nlohmann::json::object();
  for (int c : output_columns(h, scene)) {
    const Eigen::VectorXd col = h.displacement.col(c);
    j["displacement"][h.labels[c]] = std::vector<double>(col.data(), col.data() + col.size());
  }
  if (scene_effects(scene).any()) {  // the nonlinear path: its stick/slip/kink events
    j["events"] = nlohmann::json::array();
    for (const SimulationEvent& e : h.events)
      j["events"].push_back(
          {{"time_s", e.time}, {"element", vehicle.elements.at(e.element).name}, {"kind", to_string(e.kind)}});
    j["integration_steps"] = h.steps_taken;
  }
  out << j.dump() << "\n";
}

void write_history_csv(std::ostream& out, const TimeHistory& h, const Scene& scene) {
  const std::vector<int> columns = output_columns(h, scene);
  out << std::setprecision(10) << "time_s";
  for (int c : columns) out << "," << h.labels[c];
  out << "\n";
  for (int i = 0; i < h.time.size(); ++i) {
    out << h.time(i);
    for (int c : columns) out << "," << h.displacement(i, c);
    out << "\n";
  }
}

}  // namespace

void write_time_history(std::ostream& out, const TimeHistory& history, const Scene& scene, const Vehicle& vehicle,
                        OutputFormat format) {
  switch (format) {
    case OutputFormat::csv: write_history_csv(out, history, scene); break;
    case OutputFormat::json: write_history_json(out, history, scene, vehicle); break;
    default: throw std::invalid_argument(report::unwritten_format("write_time_history", "csv or json", format));
  }
}

void write_spectra(std::ostream& out, const OutputSpectra& spectra, OutputFormat format) {
  if (format != OutputFormat::csv)
    throw std::invalid_argument(report::unwritten_format("write_spectra", "csv", format));
  out << std::setprecision(10) << "frequency_hz";
  for (const std::string& dof : spectra.dofs) out << "," << dof;
  out << "\n";
  const std::vector<Spectrum>& s = spectra.spectra;
  for (Eigen::Index b = 0; !s.empty() && b < s.front().amplitude.size(); ++b) {
    out << s.front().frequency(b);
    for (const Spectrum& spectrum : s) out << "," << spectrum.amplitude(b);
    out << "\n";
  }
}

}  // namespace railmodal
