// A scene's simulation for programs: time histories as CSV or JSON, spectra as CSV. Both are
// written as text goes, never built whole in memory: a CSV history row by row as the
// simulation runs (CsvHistoryWriter), a JSON one from its record a bounded chunk at a time.
#include "railmodal/simulation_report.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "report/json_writer.hpp"
#include "report/number_text.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"
#include "shortest_text.hpp"
#include "simulate/speed_profile.hpp"

namespace railmodal {
namespace {

// The speed profile of a scene that ramps its speed ([simulation] final_speed), which the
// histories write beside the samples (the speed is not otherwise in them: user audit
// 2026-11-28b, F9 b); none at a constant speed, whose outputs stay as they were.
std::optional<simulate::SpeedProfile> ramp(const Scene& scene) {
  if (!scene.simulation || !(scene.simulation->final_speed > 0.0)) return std::nullopt;
  const SimulationSpec& s = *scene.simulation;
  return simulate::speed_profile(s.speed, s.final_speed, s.duration);
}

// A JSON array of numbers, compact, as number_text writes them (null for NaN and infinities, as
// nlohmann::json wrote them), a bounded chunk of text at a time.
void write_numbers(std::ostream& out, const Eigen::Ref<const Eigen::VectorXd>& values) {
  std::string text = "[";
  char number[report::kNumberTextMax];
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (i > 0) text += ',';
    if (std::isfinite(values(i)))
      text.append(number, report::write_number(number, values(i), report::NumberStyle::json));
    else
      text += "null";
    if (text.size() > (1 << 16)) out.write(text.data(), static_cast<std::streamsize>(text.size())), text.clear();
  }
  text += ']';
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

std::string json_string(const std::string& text) {
  std::string quoted;
  report::append_json_string(quoted, text);
  return quoted;
}

// {"displacement", "events", "integration_steps", "scene", "speed_m_s", "time_s"}: the keys in the order a
// nlohmann::json object (a std::map) wrote them, so the text kept the layout its dump() gave.
void write_history_json(std::ostream& out, const TimeHistory& h, const Scene& scene, const Vehicle& vehicle) {
  std::map<std::string, int> columns;  // by label, as the object orders its keys
  for (int c : output_columns(h, scene)) columns.emplace(h.labels[c], c);
  out << "{\"displacement\":{";
  for (auto at = columns.begin(); at != columns.end(); ++at) {
    out << (at == columns.begin() ? "" : ",") << json_string(at->first) << ':';
    write_numbers(out, h.displacement.col(at->second));
  }
  out << '}';
  if (scene_effects(scene).any()) {  // the nonlinear path: its stick/slip/kink events
    out << ",\"events\":[";
    for (size_t e = 0; e < h.events.size(); ++e)
      out << (e == 0 ? "" : ",") << "{\"element\":" << json_string(vehicle.elements.at(h.events[e].element).name)
          << ",\"kind\":" << json_string(to_string(h.events[e].kind)) << ",\"time_s\":"
          << (std::isfinite(h.events[e].time) ? report::number_text(h.events[e].time, report::NumberStyle::json)
                                              : "null")
          << '}';
    out << "],\"integration_steps\":" << h.steps_taken;
  }
  out << ",\"scene\":" << json_string(scene.name);
  if (const auto profile = ramp(scene)) {
    out << ",\"speed_m_s\":";
    write_numbers(out, h.time.unaryExpr([&](double t) { return profile->speed(t); }).eval());
  }
  out << ",\"time_s\":";
  write_numbers(out, h.time);
  out << "}\n";
}

// One CSV row of numbers, as number_text writes them (inf and nan as iostreams wrote them).
// A ramp's speed comes after the time, in km/h to 15 digits (the precision it has: 3.6·V(t) of
// a speed given in km/h, without the round-off of the conversions: "150", not
// "150.00000000000003").
void append_row(std::string& text, double first, const std::optional<simulate::SpeedProfile>& profile,
                const Eigen::Ref<const Eigen::MatrixXd>& values, Eigen::Index row, const std::vector<int>& columns) {
  char number[report::kNumberTextMax];
  text.append(number, report::write_number(number, first, report::NumberStyle::csv));
  if (profile) text += ',' + shortest_text(report::kKmh * profile->speed(first), 15);
  for (int c : columns) {
    text += ',';
    text.append(number, report::write_number(number, values(row, c), report::NumberStyle::csv));
  }
  text += '\n';
}

}  // namespace

CsvHistoryWriter::CsvHistoryWriter(std::ostream& out, const Scene& scene) : out_(out), scene_(scene) {}

void CsvHistoryWriter::begin(const std::vector<std::string>& labels, Eigen::Index) {
  columns_ = output_columns(labels, scene_);
  out_ << report::csv_heading("time", "s");
  if (ramp(scene_)) out_ << "," << report::csv_heading("speed", "km/h");
  for (int c : columns_)
    out_ << "," << report::csv_field(report::csv_heading(labels[c], report::displacement_unit(labels[c])));
  out_ << "\n";
}

void CsvHistoryWriter::write(const Eigen::Ref<const Eigen::VectorXd>& time,
                             const Eigen::Ref<const Eigen::MatrixXd>& displacement,
                             const Eigen::Ref<const Eigen::MatrixXd>&) {
  std::string text;
  const std::optional<simulate::SpeedProfile> profile = ramp(scene_);
  for (Eigen::Index i = 0; i < time.size(); ++i) {
    append_row(text, time(i), profile, displacement, i, columns_);
    if (text.size() > (1 << 16)) out_.write(text.data(), static_cast<std::streamsize>(text.size())), text.clear();
  }
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
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
  out << report::csv_heading("frequency", "Hz");  // spectra of displacements
  for (const std::string& dof : spectra.dofs)
    out << "," << report::csv_field(report::csv_heading(dof, report::displacement_unit(dof)));
  out << "\n";
  const std::vector<Spectrum>& s = spectra.spectra;
  std::string text;
  char number[report::kNumberTextMax];
  for (Eigen::Index b = 0; !s.empty() && b < s.front().amplitude.size(); ++b) {
    text.append(number, report::write_number(number, s.front().frequency(b), report::NumberStyle::csv));
    for (const Spectrum& spectrum : s) {
      text += ',';
      text.append(number, report::write_number(number, spectrum.amplitude(b), report::NumberStyle::csv));
    }
    text += '\n';
    if (text.size() > (1 << 16)) out.write(text.data(), static_cast<std::streamsize>(text.size())), text.clear();
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace railmodal
