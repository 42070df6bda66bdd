// A scene's simulation for programs: time histories as CSV or JSON, spectra as CSV. Both are
// written as text goes, never built whole in memory: a CSV history row by row as the
// simulation runs (CsvHistoryWriter), a JSON one from its record a bounded chunk at a time.
#include "railmodal/simulation_report.hpp"

#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"

namespace railmodal {
namespace {

// Numbers as nlohmann::json writes them (the shortest text that reads back the same double;
// null for NaN and infinities), without a document of them all: a chunk at a time.
void write_numbers(std::ostream& out, const Eigen::Ref<const Eigen::VectorXd>& values) {
  constexpr Eigen::Index kChunk = 4096;
  out << '[';
  for (Eigen::Index first = 0; first < values.size(); first += kChunk) {
    const Eigen::Index count = std::min(kChunk, values.size() - first);
    const std::string text =
        nlohmann::json(std::vector<double>(values.data() + first, values.data() + first + count)).dump();
    if (first > 0) out << ',';
    out.write(text.data() + 1, static_cast<std::streamsize>(text.size() - 2));  // without its brackets
  }
  out << ']';
}

// {"displacement", "events", "integration_steps", "scene", "time_s"}: the keys in the order a
// nlohmann::json object (a std::map) writes them, so the text is the one its dump() gave.
void write_history_json(std::ostream& out, const TimeHistory& h, const Scene& scene, const Vehicle& vehicle) {
  using nlohmann::json;
  std::map<std::string, int> columns;  // by label, as the object orders its keys
  for (int c : output_columns(h, scene)) columns.emplace(h.labels[c], c);
  out << "{\"displacement\":{";
  for (auto at = columns.begin(); at != columns.end(); ++at) {
    out << (at == columns.begin() ? "" : ",") << json(at->first).dump() << ':';
    write_numbers(out, h.displacement.col(at->second));
  }
  out << '}';
  if (scene_effects(scene).any()) {  // the nonlinear path: its stick/slip/kink events
    out << ",\"events\":[";
    for (size_t e = 0; e < h.events.size(); ++e)
      out << (e == 0 ? "" : ",")
          << json({{"time_s", h.events[e].time},
                   {"element", vehicle.elements.at(h.events[e].element).name},
                   {"kind", to_string(h.events[e].kind)}})
                 .dump();
    out << "],\"integration_steps\":" << json(h.steps_taken).dump();
  }
  out << ",\"scene\":" << json(scene.name).dump() << ",\"time_s\":";
  write_numbers(out, h.time);
  out << "}\n";
}

}  // namespace

CsvHistoryWriter::CsvHistoryWriter(std::ostream& out, const Scene& scene) : out_(out), scene_(scene) {}

void CsvHistoryWriter::begin(const std::vector<std::string>& labels, Eigen::Index) {
  columns_ = output_columns(labels, scene_);
  out_ << std::setprecision(10) << report::csv_heading("time", "s");
  for (int c : columns_)
    out_ << "," << report::csv_field(report::csv_heading(labels[c], report::displacement_unit(labels[c])));
  out_ << "\n";
}

void CsvHistoryWriter::write(const Eigen::Ref<const Eigen::VectorXd>& time,
                             const Eigen::Ref<const Eigen::MatrixXd>& displacement,
                             const Eigen::Ref<const Eigen::MatrixXd>&) {
  for (Eigen::Index i = 0; i < time.size(); ++i) {
    out_ << time(i);
    for (int c : columns_) out_ << "," << displacement(i, c);
    out_ << "\n";
  }
}

void write_time_history(std::ostream& out, const TimeHistory& history, const Scene& scene, const Vehicle& vehicle,
                        OutputFormat format) {
  switch (format) {
    case OutputFormat::csv: {
      CsvHistoryWriter writer(out, scene);
      writer.begin(history.labels, history.time.size());
      writer.write(history.time, history.displacement, history.displacement);
      break;
    }
    case OutputFormat::json: write_history_json(out, history, scene, vehicle); break;
    default: throw std::invalid_argument(report::unwritten_format("write_time_history", "csv or json", format));
  }
}

void write_spectra(std::ostream& out, const OutputSpectra& spectra, OutputFormat format) {
  if (format != OutputFormat::csv)
    throw std::invalid_argument(report::unwritten_format("write_spectra", "csv", format));
  out << std::setprecision(10) << report::csv_heading("frequency", "Hz");  // spectra of displacements
  for (const std::string& dof : spectra.dofs)
    out << "," << report::csv_field(report::csv_heading(dof, report::displacement_unit(dof)));
  out << "\n";
  const std::vector<Spectrum>& s = spectra.spectra;
  for (Eigen::Index b = 0; !s.empty() && b < s.front().amplitude.size(); ++b) {
    out << s.front().frequency(b);
    for (const Spectrum& spectrum : s) out << "," << spectrum.amplitude(b);
    out << "\n";
  }
}

}  // namespace railmodal
