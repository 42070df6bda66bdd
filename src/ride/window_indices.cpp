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

namespace {

// The running sum of squares over one restart interval of running_rms: out[i] for i in
// [start, end), from the window's sum at `start` (a recursion, one add and one subtract a
// sample). kChains intervals run side by side: their recursions are independent (each restarts
// from its own window sum), so they overlap in the processor where one interval at a time waits
// on each add in turn; each interval's operations are the same, in the same order.
constexpr int kChains = 8;

void running_sums(const Eigen::VectorXd& values, Eigen::Index samples, Eigen::Index start, double* out) {
  const Eigen::Index n = values.size();
  const double* v = values.data();
  const Eigen::Index first = std::max<Eigen::Index>(0, start + 1 - samples);
  double sum = values.segment(first, start + 1 - first).squaredNorm();
  out[start] = sum;
  const Eigen::Index end = std::min(n, start + samples);
  for (Eigen::Index i = start + 1; i < end; ++i) {
    sum += v[i] * v[i];
    if (i >= samples) sum -= v[i - samples] * v[i - samples];
    out[i] = sum;
  }
}

// kChains whole intervals from `start` (start ≥ samples, so every sample drops one).
void running_sums_side_by_side(const Eigen::VectorXd& values, Eigen::Index samples, Eigen::Index start, double* out) {
  const double* v = values.data();
  double sum[kChains];
  for (int c = 0; c < kChains; ++c) {
    const Eigen::Index at = start + c * samples;
    sum[c] = values.segment(at + 1 - samples, samples).squaredNorm();
    out[at] = sum[c];
  }
  for (Eigen::Index i = 1; i < samples; ++i)
    for (int c = 0; c < kChains; ++c) {
      const Eigen::Index at = start + c * samples + i;
      sum[c] += v[at] * v[at];
      sum[c] -= v[at - samples] * v[at - samples];
      out[at] = sum[c];
    }
}

}  // namespace

void running_rms(const Eigen::VectorXd& values, Eigen::Index samples, Eigen::VectorXd* out) {
  const Eigen::Index n = values.size();
  out->resize(n);
  double* o = out->data();
  // A running sum of squares, recomputed every `samples` steps so its rounding cannot build up;
  // the sums first (a recursion), then the square roots over all of them.
  Eigen::Index start = 0;
  if (start < n) running_sums(values, samples, start, o), start += samples;
  for (; start + kChains * samples <= n; start += kChains * samples) running_sums_side_by_side(values, samples, start, o);
  for (; start < n; start += samples) running_sums(values, samples, start, o);
  const Eigen::Index head = std::min(n, samples);
  for (Eigen::Index i = 0; i < head; ++i) o[i] = std::sqrt(std::max(0.0, o[i]) / static_cast<double>(i + 1));
  const double whole = static_cast<double>(samples);
  for (Eigen::Index i = head; i < n; ++i) o[i] = std::sqrt(std::max(0.0, o[i]) / whole);
}

Eigen::VectorXd running_rms(const Eigen::VectorXd& values, Eigen::Index samples) {
  Eigen::VectorXd out;
  running_rms(values, samples, &out);
  return out;
}

}  // namespace railmodal::ride
