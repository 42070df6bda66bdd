// Root tracking by eigenvector continuity (see root_tracking.hpp for the cost and why).
#include "stability/root_tracking.hpp"

#include <algorithm>
#include <complex>
#include <limits>

namespace railmodal::stability {

double modal_assurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  const double na = a.squaredNorm(), nb = b.squaredNorm();
  if (na == 0.0 || nb == 0.0) return 0.0;
  return std::norm(a.dot(b)) / (na * nb);
}

// The shortest-augmenting-path form of the Hungarian method (Kuhn 1955, Munkres 1957; with
// row and column potentials as in Jonker & Volgenant 1987): rows are added one at a time and
// each is placed along the cheapest path in reduced costs.
std::vector<int> minimum_cost_assignment(const std::vector<std::vector<double>>& cost) {
  const int n = static_cast<int>(cost.size());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0);
  std::vector<int> row_of(n + 1, 0), way(n + 1, 0);  // 1-based; column 0 is the root of the search
  for (int i = 1; i <= n; ++i) {
    row_of[0] = i;
    int j0 = 0;
    std::vector<double> min_to(n + 1, inf);
    std::vector<bool> used(n + 1, false);
    do {
      used[j0] = true;
      const int i0 = row_of[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double reduced = cost[i0 - 1][j - 1] - u[i0] - v[j];
        if (reduced < min_to[j]) min_to[j] = reduced, way[j] = j0;
        if (min_to[j] < delta) delta = min_to[j], j1 = j;
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j])
          u[row_of[j]] += delta, v[j] -= delta;
        else
          min_to[j] -= delta;
      }
      j0 = j1;
    } while (row_of[j0] != 0);
    do {
      const int j1 = way[j0];
      row_of[j0] = row_of[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> column(n, -1);
  for (int j = 1; j <= n; ++j)
    if (row_of[j] > 0) column[row_of[j] - 1] = j - 1;
  return column;
}

namespace {

double relative_distance(std::complex<double> a, std::complex<double> b) {
  const double scale = std::abs(a) + std::abs(b);
  return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}


// The root each path continues to when the eigenvalues alone decide, or an empty vector.
std::vector<int> clear_continuation(const std::vector<std::complex<double>>& predicted, const Eigen::VectorXcd& now) {
  const int n = static_cast<int>(now.size());
  std::vector<int> next(n, -1);
  std::vector<bool> taken(n, false);
  std::vector<std::pair<double, int>> order(n);
  for (int p = 0; p < n; ++p) {
    for (int j = 0; j < n; ++j) order[j] = {relative_distance(now(j), predicted[p]), j};
    std::sort(order.begin(), order.end());
    const std::complex<double> best = now(order[0].second);
    int k = 1;
    while (k < n && relative_distance(now(order[k].second), best) <= kTwins) ++k;
    if (k < n && !(order[0].first <= 0.2 * order[k].first)) return {};
    int pick = 0;
    while (pick < k && taken[order[pick].second]) ++pick;
    if (pick == k) return {};  // every root of that value is another path's
    next[p] = order[pick].second;
    taken[next[p]] = true;
  }
  return next;
}

}  // namespace

RootPaths track_roots(const std::vector<SpeedRoots>& speeds, std::vector<int>* missing) {
  RootPaths paths;
  if (speeds.empty()) return paths;
  const int n = static_cast<int>(speeds[0].values.size());
  std::vector<int> first(n);
  for (int p = 0; p < n; ++p) first[p] = p;
  paths.root.push_back(first);
  paths.continuity.push_back(std::vector<double>(n, 1.0));
  std::vector<std::vector<double>> cost(n, std::vector<double>(n));
  std::vector<std::complex<double>> predicted(n);
  for (size_t s = 1; s < speeds.size(); ++s) {
    const SpeedRoots& now = speeds[s];
    const SpeedRoots& before = speeds[s - 1];
    const std::vector<int>& last = paths.root[s - 1];
    for (int p = 0; p < n; ++p) {
      predicted[p] = before.values(last[p]);
      if (s >= 2) predicted[p] = 2.0 * predicted[p] - speeds[s - 2].values(paths.root[s - 2][p]);
    }
    std::vector<int> next = clear_continuation(predicted, now.values);
    std::vector<double> continuity(n, 1.0);
    if (next.empty()) {
      const bool shapes = before.shapes.size() > 0 && now.shapes.size() > 0;
      Eigen::MatrixXd mac = Eigen::MatrixXd::Ones(n, n);
      // All MACs at once: |Uᴴ_before U_now|² (the shapes have unit norm or are zero).
      if (shapes) mac = (before.shapes.adjoint() * now.shapes).cwiseAbs2();
      for (int p = 0; p < n; ++p)
        for (int j = 0; j < n; ++j)
          cost[p][j] = (1.0 - mac(last[p], j)) + relative_distance(now.values(j), predicted[p]);
      next = minimum_cost_assignment(cost);
      if (shapes) {
        for (int p = 0; p < n; ++p) continuity[p] = mac(last[p], next[p]);
      } else {
        if (before.shapes.size() == 0) missing->push_back(static_cast<int>(s) - 1);
        if (now.shapes.size() == 0) missing->push_back(static_cast<int>(s));
      }
    }
    paths.root.push_back(std::move(next));
    paths.continuity.push_back(std::move(continuity));
  }
  std::sort(missing->begin(), missing->end());
  missing->erase(std::unique(missing->begin(), missing->end()), missing->end());
  return paths;
}

}  // namespace railmodal::stability
