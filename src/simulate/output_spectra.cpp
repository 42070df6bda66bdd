// What a scene's simulation outputs: the columns it names, and their spectra.
#include <algorithm>

#include "railmodal/scene_simulation.hpp"
#include "simulate/record_spectrum.hpp"

namespace railmodal {

std::vector<int> output_columns(const TimeHistory& history, const Scene& scene) {
  const std::vector<std::string>& outputs = scene.simulation->outputs;
  std::vector<int> columns;
  for (int c = 0; c < static_cast<int>(history.labels.size()); ++c)
    if (outputs.empty() || std::find(outputs.begin(), outputs.end(), history.labels[c]) != outputs.end())
      columns.push_back(c);
  return columns;
}

OutputSpectra output_spectra(const TimeHistory& history, const Scene& scene) {
  const double fs = 1.0 / scene.simulation->time_step;
  SpectrumAnalyzer analyzer(history.time.size(), record_spectrum_options(history.time.size()));
  OutputSpectra out;
  for (int c : output_columns(history, scene)) {
    out.dofs.push_back(history.labels[c]);
    out.spectra.push_back(analyzer.compute(history.displacement.col(c), fs));
  }
  return out;
}

}  // namespace railmodal
