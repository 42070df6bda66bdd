// Adaptive refinement of a damped resonance peak: golden-section search on a bracket.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "railmodal/response.hpp"
#include "response/golden_section.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

Peak refine_peak(const LinearSystem& system, const ModalResult& modes, const ExcitationSource& source,
                 const OutputRequest& output, double low, double high, double relative_tolerance,
                 double friction_reference_amplitude, AnalysisSummary* summary) {
  if (!(low > 0.0) || !(high > low) || !(relative_tolerance > 0.0))
    throw std::invalid_argument("refine_peak: need 0 < low < high and a positive tolerance");
  if (summary) *summary = AnalysisSummary{};
  StageClock clock(summary);  // no clock, no strings without a summary
  Peak peak;
  OutputRequest amplitude_only = output;
  amplitude_only.phase = false;
  auto amplitude = [&](double speed) {
    ++peak.evaluations;
    const auto curves =
        amplitude_curves(system, modes, source, 0, {amplitude_only}, {speed}, friction_reference_amplitude);
    if (curves[0].unbounded[0]) peak.unbounded = true;
    return curves[0].amplitudes[0];
  };
  // Golden section keeps one interior point per step: the bracket shrinks by 0.618 per solve.
  const auto g = response::golden_section(low, high, relative_tolerance, amplitude, [&](double a) {
    return peak.unbounded ? std::nan("") : a;
  });
  peak.speed = g.fc >= g.fd ? g.c : g.d;
  peak.amplitude = std::max(g.fc, g.fd);
  clock.lap("search");
  if (summary) {
    summary->analysis = "resonance peak";
    summary->method = "golden-section search to a bracket of relative_tolerance × speed, one direct solve per "
                      "harmonic and evaluation";
    summary->checks.push_back({"evaluations", static_cast<double>(peak.evaluations),
                               std::numeric_limits<double>::infinity(), true});
    summary->checks.push_back({"unbounded speeds met (no finite peak)", peak.unbounded ? 1.0 : 0.0,
                               std::numeric_limits<double>::infinity(), true});
  }
  return peak;
}

}  // namespace railmodal
