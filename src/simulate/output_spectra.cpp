// What a scene's simulation outputs: the columns it names, their record, and their spectra.
#include <algorithm>

#include "railmodal/scene_simulation.hpp"
#include "simulate/record_memory.hpp"
#include "simulate/record_spectrum.hpp"

namespace railmodal {

std::vector<int> output_columns(const std::vector<std::string>& labels, const Scene& scene) {
  const std::vector<std::string>& outputs = scene.simulation->outputs;
  std::vector<int> columns;
  for (int c = 0; c < static_cast<int>(labels.size()); ++c)
    if (outputs.empty() || std::find(outputs.begin(), outputs.end(), labels[c]) != outputs.end()) columns.push_back(c);
  return columns;
}

std::vector<int> output_columns(const TimeHistory& history, const Scene& scene) {
  return output_columns(history.labels, scene);
}

OutputRecord::OutputRecord(const Scene& scene, bool for_spectra, double memory_limit)
    : scene_(scene), for_spectra_(for_spectra), memory_limit_(memory_limit) {}

void OutputRecord::begin(const std::vector<std::string>& labels, Eigen::Index samples) {
  columns_ = output_columns(labels, scene_);
  const int outputs = static_cast<int>(columns_.size());
  // The time and each output: 8 bytes a sample; spectra: M/2 + 1 = 2N + 1 bins of 8 bytes for
  // each output, and the transform's 120 (its window 8 N, input 32 N, output 32 N, and FFTW's
  // own buffers for M = 4N: 271 bytes a sample measured in all for 6 outputs, 272 estimated).
  const double bytes_per_sample = 8.0 * (1 + outputs) + (for_spectra_ ? 16.0 * outputs + 120.0 : 0.0);
  simulate::require_record_fits(for_spectra_ ? "the output spectra (which take the whole record)"
                                             : "the JSON history (written a DOF at a time, so held whole)",
                                static_cast<double>(samples), outputs, bytes_per_sample, memory_limit_);
  record_ = TimeHistory();
  for (int c : columns_) record_.labels.push_back(labels[c]);
  record_.time.resize(samples);
  record_.displacement.resize(samples, outputs);
  next_ = 0;
}

void OutputRecord::write(const Eigen::Ref<const Eigen::VectorXd>& time,
                         const Eigen::Ref<const Eigen::MatrixXd>& displacement,
                         const Eigen::Ref<const Eigen::MatrixXd>&) {
  const Eigen::Index count = time.size();
  record_.time.segment(next_, count) = time;
  for (size_t k = 0; k < columns_.size(); ++k)
    record_.displacement.col(static_cast<Eigen::Index>(k)).segment(next_, count) = displacement.col(columns_[k]);
  next_ += count;
}

TimeHistory OutputRecord::history(TimeHistory result) {
  result.labels = std::move(record_.labels);
  result.time = std::move(record_.time);
  result.displacement = std::move(record_.displacement);
  result.velocity.resize(0, 0);
  return result;
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
