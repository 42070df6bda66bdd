// railmodal — writing a scene's simulation: the time histories of its outputs (CSV, or JSON
// with a nonlinear scene's events) and their amplitude spectra (CSV).
//
//   #include <railmodal/railmodal.hpp>
//   #include <fstream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/leaf_spring_drop_test.toml");
//     railmodal::Vehicle vehicle = railmodal::load_vehicle(scene.vehicle_file);
//     railmodal::TimeHistory history = railmodal::simulate_scene(scene, vehicle);
//     std::ofstream out("/dev/null");  // a file such as history.csv
//     railmodal::write_time_history(out, history, scene, vehicle, railmodal::OutputFormat::csv);
//     railmodal::OutputSpectra spectra = railmodal::output_spectra(history, scene);
//     railmodal::write_spectra(out, spectra, railmodal::OutputFormat::csv);
//   }
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "railmodal/output_format.hpp"
#include "railmodal/scene_simulation.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal {

/// Writes csv or json (std::invalid_argument for table, markdown and html) of the DOFs the
/// scene's simulation outputs (output_columns), numbers in the shortest text that reads back as
/// the same double. csv: "time [s]" and one column per DOF ("body.bounce [m]", "body.pitch [rad]"), one row per
/// sample; json: {"scene", "time_s", "displacement": {label: [...]}}, and for a nonlinear
/// scene "events": [{"time_s", "element", "kind"}] and "integration_steps". `vehicle` names the
/// events' elements. The history may be an OutputRecord's (its output columns only). The text
/// is streamed, never held whole.
void write_time_history(std::ostream& out, const TimeHistory& history, const Scene& scene, const Vehicle& vehicle,
                        OutputFormat format);

/// Writes the csv of write_time_history as the simulation produces it, row by row, holding no
/// samples: pass it to simulate_scene as a sink (and an OutputRecord beside it for spectra).
class CsvHistoryWriter final : public HistorySink {
 public:
  CsvHistoryWriter(std::ostream& out, const Scene& scene);
  void begin(const std::vector<std::string>& labels, Eigen::Index samples) override;  ///< the header
  void write(const Eigen::Ref<const Eigen::VectorXd>& time, const Eigen::Ref<const Eigen::MatrixXd>& displacement,
             const Eigen::Ref<const Eigen::MatrixXd>& velocity) override;

 private:
  std::ostream& out_;
  const Scene& scene_;
  std::vector<int> columns_;
};

/// Writes csv (std::invalid_argument for every other format): "frequency [Hz]" and one column
/// per DOF ("body.bounce [m]"), one row per bin up to the Nyquist frequency, each number in the
/// shortest text that reads back as the same double.
void write_spectra(std::ostream& out, const OutputSpectra& spectra, OutputFormat format);

}  // namespace railmodal
