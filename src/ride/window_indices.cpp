#include "ride/window_indices.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "railmodal/comfort_weighting.hpp"

namespace railmodal::ride {

Eigen::VectorXd window_rms(const Eigen::VectorXd& values, Eigen::Index samples) {
  if (samples < 1) throw std::invalid_argument("window_rms: a window holds at least one sample");
  const Eigen::Index count = values.size() / samples;
  Eigen::VectorXd out(count);
  for (Eigen::Index w = 0; w < count; ++w)
    out(w) = std::sqrt(values.segment(w * samples, samples).squaredNorm() / static_cast<double>(samples));
  return out;
}

double percentile95(const Eigen::VectorXd& values) {
  if (values.size() == 0) throw std::invalid_argument("percentile95: no values");
  std::vector<double> sorted(values.data(), values.data() + values.size());
  std::sort(sorted.begin(), sorted.end());
  const double rank = 0.95 * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<size_t>(std::floor(rank));
  if (below + 1 >= sorted.size()) return sorted.back();
  return sorted[below] + (rank - static_cast<double>(below)) * (sorted[below + 1] - sorted[below]);
}

double zone_p95(const Eigen::VectorXd& window_values, Eigen::Index zone, std::string* note) {
  const Eigen::Index zones = window_values.size() / zone;
  if (zones == 0) {
    if (note)
      *note = "P95 over the " + std::to_string(window_values.size()) + " complete windows of the run, fewer than the " +
              std::to_string(zone) + " of an EN 12299 zone";
    return percentile95(window_values);
  }
  const double largest = zone_p95s(window_values, zone).maxCoeff();
  if (note)
    *note = "P95: the largest of " + std::to_string(zones) + " complete zone(s) of " + std::to_string(zone) +
            " windows";
  return largest;
}

Eigen::VectorXd zone_p95s(const Eigen::VectorXd& window_values, Eigen::Index zone) {
  const Eigen::Index zones = window_values.size() / zone;
  if (zones == 0) return Eigen::VectorXd::Constant(1, percentile95(window_values));
  Eigen::VectorXd out(zones);
  for (Eigen::Index z = 0; z < zones; ++z) out(z) = percentile95(window_values.segment(z * zone, zone));
  return out;
}

double zone_nmv(const Eigen::VectorXd* longitudinal, const Eigen::VectorXd* lateral, const Eigen::VectorXd* vertical) {
  const Eigen::VectorXd* axes[3] = {longitudinal, lateral, vertical};
  Eigen::Index zones = 0;
  for (const Eigen::VectorXd* a : axes)
    if (a) {
      if (zones && a->size() != zones) throw std::invalid_argument("zone_nmv: the axes have different zone counts");
      zones = a->size();
    }
  double largest = 0.0;
  for (Eigen::Index z = 0; z < zones; ++z) {
    double p95[3];
    for (int k = 0; k < 3; ++k) p95[k] = axes[k] ? (*axes[k])(z) : 0.0;
    largest = std::max(largest, en12299_nmv(p95[0], p95[1], p95[2]));
  }
  return largest;
}

Eigen::VectorXd running_rms(const Eigen::VectorXd& values, Eigen::Index samples) {
  const Eigen::Index n = values.size();
  Eigen::VectorXd out(n);
  // A running sum of squares, recomputed every `samples` steps so its rounding cannot build up;
  // the sums first (a recursion), then the square roots over all of them in one loop.
  for (Eigen::Index start = 0; start < n; start += samples) {
    const Eigen::Index first = std::max<Eigen::Index>(0, start + 1 - samples);
    double sum = values.segment(first, start + 1 - first).squaredNorm();
    out(start) = sum;
    const Eigen::Index end = std::min(n, start + samples);
    for (Eigen::Index i = start + 1; i < end; ++i) {
      sum += values(i) * values(i);
      if (i >= samples) sum -= values(i - samples) * values(i - samples);
      out(i) = sum;
    }
  }
  for (Eigen::Index i = 0; i < n; ++i)
    out(i) = std::sqrt(std::max(0.0, out(i)) / static_cast<double>(std::min<Eigen::Index>(i + 1, samples)));
  return out;
}

}  // namespace railmodal::ride
