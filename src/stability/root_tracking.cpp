// Root tracking by eigenvector continuity (see root_tracking.hpp for the cost and why).
#include "stability/root_tracking.hpp"

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
        if (used[j]) u[row_of[j]] += delta, v[j] -= delta;
        else min_to[j] -= delta;
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

RootPaths track_roots(const std::vector<SpeedRoots>& speeds) {
  RootPaths paths;
  if (speeds.empty()) return paths;
  const int n = static_cast<int>(speeds[0].values.size());
  std::vector<int> first(n);
  for (int p = 0; p < n; ++p) first[p] = p;
  paths.root.push_back(first);
  paths.continuity.push_back(std::vector<double>(n, 1.0));
  std::vector<std::vector<double>> cost(n, std::vector<double>(n));
  for (size_t s = 1; s < speeds.size(); ++s) {
    const SpeedRoots& now = speeds[s];
    const SpeedRoots& before = speeds[s - 1];
    const std::vector<int>& last = paths.root[s - 1];
    // All MACs at once: |Uᴴ_before U_now|² (the shapes have unit norm or are zero).
    const Eigen::MatrixXd mac = (before.shapes.adjoint() * now.shapes).cwiseAbs2();
    for (int p = 0; p < n; ++p) {
      std::complex<double> predicted = before.values(last[p]);
      if (s >= 2) predicted = 2.0 * predicted - speeds[s - 2].values(paths.root[s - 2][p]);
      for (int j = 0; j < n; ++j) {
        const std::complex<double> value = now.values(j);
        const double scale = std::abs(value) + std::abs(predicted);
        const double distance = scale > 0.0 ? std::abs(value - predicted) / scale : 0.0;
        cost[p][j] = (1.0 - mac(last[p], j)) + distance;
      }
    }
    const std::vector<int> next = minimum_cost_assignment(cost);
    std::vector<double> continuity(n);
    for (int p = 0; p < n; ++p) continuity[p] = mac(last[p], next[p]);
    paths.root.push_back(next);
    paths.continuity.push_back(std::move(continuity));
  }
  return paths;
}

}  // namespace railmodal::stability
