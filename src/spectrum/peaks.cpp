#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "railmodal/spectrum.hpp"
#include "require_valid.hpp"
#include "shortest_text.hpp"
#include "spectrum/windows.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {
namespace {

// Does the amplitude fall to `level` on the side of bin k given by `step` before it rises
// above a[k]? Reaching the end of the spectrum counts as falling.
bool falls_to(const Eigen::VectorXd& a, Eigen::Index k, Eigen::Index step, double level) {
  for (Eigen::Index j = k + step; j >= 0 && j < a.size(); j += step) {
    if (a(j) > a(k)) return false;
    if (a(j) <= level) return true;
  }
  return true;
}

// Where, in bins, the amplitude crosses `level` on the side of bin k given by `step`
// (linear between bins), or the end of the spectrum if it never does.
double crossing(const Eigen::VectorXd& a, Eigen::Index k, Eigen::Index step, double level) {
  Eigen::Index j = k;
  while (j + step >= 0 && j + step < a.size() && a(j + step) > level) j += step;
  if (j + step < 0 || j + step >= a.size()) return static_cast<double>(j);
  const double fraction = (a(j) - level) / (a(j) - a(j + step));
  return static_cast<double>(j) + static_cast<double>(step) * fraction;
}

SpectralPeak interpolate(const Spectrum& s, Eigen::Index k, double window_half_width) {
  const Eigen::VectorXd& a = s.amplitude;
  // Parabola through the log-amplitudes at k−1, k, k+1; a neighbour below the round-off of
  // the peak (a bin-centred tone under the rectangular window) counts as round-off.
  const double floor = a(k) * std::numeric_limits<double>::epsilon();
  const double left = std::log(std::max(a(k - 1), floor)), centre = std::log(a(k)),
               right = std::log(std::max(a(k + 1), floor));
  const double delta = 0.5 * (left - right) / (left - 2.0 * centre + right);  // in [−½, ½] bin

  SpectralPeak p;
  p.bin = k;
  p.frequency = (static_cast<double>(k) + delta) * s.bin_spacing;
  // The line's offset from bin k in bins of fs/N (padding makes bins finer than that).
  p.amplitude = a(k) / spectrum::window_response(s.window, delta * s.bin_spacing / s.resolution);
  const double half = 0.5 * p.amplitude;
  const double width = (crossing(a, k, 1, half) - crossing(a, k, -1, half)) * s.bin_spacing;
  p.resolution = std::max(0.5 * width, window_half_width * s.resolution);
  return p;
}

}  // namespace

bool PeakOptions::is_valid(std::string* why) const {
  if (!(threshold > 0.0 && threshold <= 1.0))
    return invalid(why, "threshold must be in (0, 1], got " + shortest_text(threshold));
  if (!(min_dip >= 0.0 && min_dip < 1.0))
    return invalid(why, "min_dip must be in [0, 1), got " + shortest_text(min_dip));
  return true;
}

std::vector<SpectralPeak> find_peaks(const Spectrum& spectrum, const PeakOptions& options, AnalysisSummary* summary) {
  require_valid(options, "");
  const Eigen::VectorXd& a = spectrum.amplitude;
  if (a.size() < 3)
    throw std::invalid_argument("peaks need a spectrum of at least 3 bins, got " + std::to_string(a.size()));
  if (!(spectrum.bin_spacing > 0.0) || !(spectrum.resolution > 0.0))
    throw std::invalid_argument("the spectrum's bin_spacing and resolution must be positive");

  if (summary) *summary = AnalysisSummary{};
  StageClock clock(summary);  // no clock, no strings without a summary
  std::vector<Eigen::Index> maxima;
  double largest = 0.0;
  for (Eigen::Index k = 1; k + 1 < a.size(); ++k) {
    // The left end of a plateau counts once.
    if (!(a(k) > a(k - 1) && a(k) >= a(k + 1))) continue;
    const double level = a(k) * (1.0 - options.min_dip);
    if (!falls_to(a, k, -1, level) || !falls_to(a, k, 1, level)) continue;
    maxima.push_back(k);
    largest = std::max(largest, a(k));
  }
  const double window_half_width = 0.5 * window_properties(spectrum.window).half_amplitude_bandwidth;
  std::vector<SpectralPeak> peaks;
  for (Eigen::Index k : maxima)
    if (a(k) >= options.threshold * largest) peaks.push_back(interpolate(spectrum, k, window_half_width));
  clock.lap("maxima and interpolation");
  if (summary) {
    summary->analysis = "spectral peaks";
    summary->method = "local maxima with the dip min_dip asks for, parabolic interpolation of the log-amplitudes";
    constexpr double kNoLimit = std::numeric_limits<double>::infinity();
    summary->checks.push_back({"local maxima with their dip", static_cast<double>(maxima.size()), kNoLimit, true});
    summary->checks.push_back({"of them above the threshold", static_cast<double>(peaks.size()),
                               static_cast<double>(maxima.size()), true});
  }
  return peaks;
}

}  // namespace railmodal
