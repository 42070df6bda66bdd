// Branches of the root locus from the tracked root paths (see branches.hpp).
#include "stability/branches.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <utility>

#include <Eigen/QR>
#include <Eigen/SVD>

#include "stability/branch_naming.hpp"
#include "stability/damping_search.hpp"

namespace railmodal::stability {

namespace {

using cd = std::complex<double>;
constexpr double kTwoPi = 6.283185307179586476925;

// The conjugate of root r at one speed: Eigen stores the halves of a pair next to each other.
int conjugate_of(const Eigen::VectorXcd& values, int r) {
  if (values(r).imag() == 0.0) return -1;
  for (int q : {r - 1, r + 1})
    if (q >= 0 && q < values.size() && values(q) == std::conj(values(r))) return q;
  return -1;
}

// An orthonormal basis of the span of `vectors`' columns: the left singular vectors whose
// singular value is above 1e-8 of the largest (a pair at its meeting, where the two eigenvectors
// coincide, spans one direction). Empty when every column is zero.
Eigen::MatrixXcd orthonormal_span(const Eigen::MatrixXcd& vectors) {
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(vectors, Eigen::ComputeThinU);
  const Eigen::VectorXd& sigma = svd.singularValues();
  int rank = 0;
  while (rank < sigma.size() && sigma(rank) > 1e-8 * sigma(0)) ++rank;
  return svd.matrixU().leftCols(rank);
}

// How much of the span of `part` lies in the span of `whole`: cos² of the largest principal
// angle between them, the smallest singular value of Q_partᴴQ_whole squared for orthonormal bases
// (Björck and Golub, "Numerical methods for computing angles between linear subspaces", Math.
// Comp. 27 (1973) 579–594, section 3). 1 when either moves no mass (nothing to follow).
double share_within(const Eigen::MatrixXcd& part, const Eigen::MatrixXcd& whole) {
  Eigen::MatrixXcd a = orthonormal_span(part), b = orthonormal_span(whole);
  if (a.cols() == 0 || b.cols() == 0) return 1.0;
  // A pair at its meeting spans one direction (its two eigenvectors coincide: the matrix is
  // defective there, and the second direction of its invariant plane is a generalised
  // eigenvector the shapes do not hold). The other speed's plane cannot lie in that line, but
  // the line must lie in the plane: measure that instead of calling the step a veer (review of
  // 2026-11-27: a step onto a meeting would otherwise read 0).
  if (a.cols() > b.cols()) std::swap(a, b);
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(a.adjoint() * b);
  const double cosine = std::min(1.0, svd.singularValues().minCoeff());
  return cosine * cosine;
}

// The shapes of roots r1 and r2 at one speed, and with `twins` those of every root within kTwins
// of either (empty without shapes). Which twin a path continues to is not decided (track_roots:
// a symmetric vehicle's front and rear wheelsets, split by 1e-5 and less), and their
// eigenvectors are any basis of their common subspace.
Eigen::MatrixXcd pair_shapes(const SpeedRoots& roots, int r1, int r2, bool twins) {
  if (roots.shapes.size() == 0) return {};
  std::vector<int> columns{r1, r2};
  if (twins)
    for (int j = 0; j < roots.values.size(); ++j) {
      const auto close = [&](int r) {
        const double scale = std::abs(roots.values(j)) + std::abs(roots.values(r));
        return std::abs(roots.values(j) - roots.values(r)) <= kTwins * scale;
      };
      if (j != r1 && j != r2 && (close(r1) || close(r2))) columns.push_back(j);
    }
  Eigen::MatrixXcd shapes(roots.shapes.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t c = 0; c < columns.size(); ++c) shapes.col(static_cast<Eigen::Index>(c)) = roots.shapes.col(columns[c]);
  return shapes;
}

// How well a root pair's plane (the span of its two halves' shapes) at one speed continues at
// the next: the share of each speed's plane within the other's (share_within), the smaller. Where
// the pair is real or nearly real its two shapes are the eigenvectors of two real roots, and
// next to where they meet they are nearly parallel (defective at the meeting), so each one's MAC
// says nothing; the plane they span is the pair's invariant subspace (its displacement part),
// which stays continuous through the meeting as long as the pair stays apart from other roots.
// A swap with another pair changes the plane, and this sees it where the earlier rule (1 at every
// real step) did not. Twins of either root join the other speed's side (their subspace is what
// is defined, and the tracking takes twins in order). 1 when either speed has no shapes (the
// step was decided by the eigenvalues alone, within track_roots' stated bound).
double plane_continuity(const SpeedRoots& before, int b1, int b2, const SpeedRoots& now, int n1, int n2) {
  if (before.shapes.size() == 0 || now.shapes.size() == 0) return 1.0;
  return std::min(share_within(pair_shapes(before, b1, b2, false), pair_shapes(now, n1, n2, true)),
                  share_within(pair_shapes(now, n1, n2, false), pair_shapes(before, b1, b2, true)));
}

// The kinematic test. Klingel's motion has a wavelength, not a frequency: at low speed its
// frequency is about V/Λ and grows in proportion to V, where a suspension mode's stays put.
// A branch is kinematic when, at the lowest speed where it oscillates, f/(V/Λ) lies within
// [0.4, 1.25] (a bogie's wheelsets, held together, have a longer wavelength than a free
// wheelset's: the rigid bogie's is Λ·√(1 + a²f22/(l0²f11)), about twice Λ for a = 1.28 m,
// l0 = 0.75 m), and f grows with V: over a speed step of at least half that speed, f/V
// changes by less than a third.
bool kinematic(const HuntingBranch& b, const std::vector<double>& speeds, double wavelength) {
  if (!(wavelength > 0.0) || !std::isfinite(wavelength)) return false;
  const int n = static_cast<int>(speeds.size());
  int j = 0;
  while (j < n && !(b.frequency_hz[j] > 0.0)) ++j;
  if (j == n) return false;
  const double ratio = b.frequency_hz[j] / (speeds[j] / wavelength);
  if (ratio < 0.4 || ratio > 1.25) return false;
  int k = j;
  while (k < n && speeds[k] < 1.5 * speeds[j]) ++k;
  if (k == n || !(b.frequency_hz[k] > 0.0)) return false;
  const double growth = (b.frequency_hz[k] / b.frequency_hz[j]) / (speeds[k] / speeds[j]);
  return growth > 0.75 && growth < 1.33;
}

// The series damper whose relaxation −k/c a non-oscillating root lies within 5 % of, by its
// element's name ("" when none). A series damper adds the state of its force, whose own root is
// −k/c; the coupling to the suspension moves it by little (0.6 % for a yaw damper of k = 5 MN/m,
// c = 20 kN·s/m on a two-axle wagon at 10 km/h), but at higher speed it can meet a creep root and
// form a complex pair: it is then a branch, named as the relaxation it starts as.
std::string relaxation_of(const LinearSystem& system, cd value) {
  if (!overdamped_root(value)) return "";
  for (const SeriesDamperRow& d : system.series_dampers) {
    const double rate = -d.stiffness / d.damping;
    if (std::abs(value.real() - rate) <= 0.05 * std::abs(rate)) {
      const bool named = d.element >= 0 && d.element < static_cast<int>(system.vehicle.elements.size());
      return "series damper relaxation" + (named ? " (" + system.vehicle.elements[d.element].name + ")" : "");
    }
  }
  return "";
}

}  // namespace

Branches group_branches(const LinearSystem& system, const std::vector<SpeedRoots>& speeds, const RootPaths& paths,
                        double klingel_wavelength, double continuity_threshold) {
  const int ns = static_cast<int>(speeds.size());
  const int np = ns > 0 ? static_cast<int>(speeds[0].values.size()) : 0;
  std::vector<std::vector<int>> path_of(ns, std::vector<int>(np));
  for (int s = 0; s < ns; ++s)
    for (int p = 0; p < np; ++p) path_of[s][paths.root[s][p]] = p;

  // Pairs, from the highest speed down.
  std::vector<int> partner(np, -2);  // -2: not yet placed, -1: a real root
  for (int s = ns - 1; s >= 0; --s)
    for (int p = 0; p < np; ++p) {
      if (partner[p] != -2) continue;
      const int q_root = conjugate_of(speeds[s].values, paths.root[s][p]);
      if (q_root < 0) continue;
      const int q = path_of[s][q_root];
      if (q != p && partner[q] == -2) partner[p] = q, partner[q] = p;
    }

  std::vector<double> grid(ns);
  for (int s = 0; s < ns; ++s) grid[s] = speeds[s].speed;
  std::vector<int> group_of_path(np, -1);
  std::vector<std::string> group_names;
  std::vector<bool> is_branch;
  std::vector<HuntingBranch> branches;
  for (int p = 0; p < np; ++p) {
    if (group_of_path[p] >= 0) continue;
    const int q = partner[p] >= 0 ? partner[p] : -1;
    group_of_path[p] = static_cast<int>(group_names.size());
    if (q < 0) {  // a real root at every speed
      const int r = paths.root[0][p];
      const std::string relaxation = relaxation_of(system, speeds[0].values(r));
      group_names.push_back(relaxation.empty() ? root_name(system, speeds[0].shapes.col(r), false) + " (real root)"
                                               : relaxation);
      is_branch.push_back(false);
      continue;
    }
    group_of_path[q] = group_of_path[p];
    HuntingBranch b;
    int first_root = -1;
    bool rigid = true;  // both roots rigid-body at every speed
    for (int s = 0; s < ns; ++s) {
      const int rp = paths.root[s][p], rq = paths.root[s][q];
      const cd lp = speeds[s].values(rp), lq = speeds[s].values(rq);
      const double scale = root_scale(speeds[s].values);
      rigid = rigid && root_damping(lp, scale).rigid && root_damping(lq, scale).rigid;
      int r;
      if (lp.imag() > 0.0 || lq.imag() > 0.0)
        r = lp.imag() >= lq.imag() ? rp : rq;
      else
        r = lp.real() >= lq.real() ? rp : rq;
      if (s == 0) first_root = r;
      const cd value = speeds[s].values(r);
      const cd upper = value.imag() < 0.0 ? std::conj(value) : value;
      b.eigenvalues.push_back(upper);
      b.damping_ratio.push_back(root_damping(upper, scale).zeta);
      b.frequency_hz.push_back(upper.imag() / kTwoPi);
      // Where the pair is real at either end of the step (overdamped: two real roots), there is
      // no oscillation to follow: the two roots meet and leave the real axis as a complex pair,
      // and at the meeting the eigenvector is defective, so its MAC with either neighbour says
      // nothing about the tracking (the Manchester coach's wheelset pairs fell to 0.11 there and
      // failed the continuity check although every oscillation was followed). The plane the
      // pair's two shapes span does (plane_continuity): a swap of two real pairs between the
      // speeds shows there, which the earlier rule (1 at every real step) hid.
      // Nearly real counts too (Im λ under 1 % of |λ|, ζ > 0.99995, as the naming below): next
      // to the meeting the eigenvector is nearly defective as well (the coach's 0.36 at 22 km/h).
      const bool real_step = overdamped_root(upper) || (s > 0 && overdamped_root(b.eigenvalues[s - 1]));
      b.continuity.push_back(
          !real_step || s == 0 ? std::min(paths.continuity[s][p], paths.continuity[s][q])
                               : plane_continuity(speeds[s - 1], paths.root[s - 1][p], paths.root[s - 1][q],
                                                  speeds[s], rp, rq));
      if (b.continuity.back() < continuity_threshold) b.veers = true;
    }
    const cd first = speeds[0].values(first_root);
    // A pair that is overdamped at every speed (a series damper's relaxation −k/c paired with a
    // creep root by round-off: Im λ under 1 % of |λ| throughout) never oscillates: it is a real
    // root, named as one, and neither an oscillatory branch nor part of the continuity check
    // (its plane's MAC near a meeting with another real root says nothing: the coach with a yaw
    // damper failed that check at every grid, user audit 2026-11-27b, 2.1). Its ζ still counts
    // in the least-damped search, which looks at every root.
    // A pair of rigid-body roots at every speed (the split of a defective zero root by round-off:
    // the coach at zero conicity, damping_search.cpp) neither oscillates nor decays: its Im λ and
    // shapes are round-off, so it is no branch and no part of the continuity check either (the
    // coach at λ = 0 failed that check with 0.53 on it, user audit 2026-11-28, F1).
    if (rigid) {
      group_names.push_back(root_name(system, speeds[0].shapes.col(first_root), false) + " (rigid-body, neutral)");
      is_branch.push_back(false);
      continue;
    }
    if (std::all_of(b.eigenvalues.begin(), b.eigenvalues.end(), [](cd l) { return overdamped_root(l); })) {
      const std::string relaxation = relaxation_of(system, first);
      group_names.push_back(relaxation.empty() ? root_name(system, speeds[0].shapes.col(first_root), false) + " (real root)"
                                               : relaxation);
      is_branch.push_back(false);
      continue;
    }
    // An overdamped pair at the lowest speed (two real roots, or a pair whose Im λ is under 1 %
    // of |λ|: ζ > 0.99995, a decay of e^−600 per cycle, shown as 0 Hz and ζ = 100 %) is not
    // hunting there: it does not oscillate.
    b.name = relaxation_of(system, first);
    if (b.name.empty())
      b.name = root_name(system, speeds[0].shapes.col(first_root), !overdamped_root(first));
    if (kinematic(b, grid, klingel_wavelength)) b.name += " (kinematic)";
    group_names.push_back(b.name);
    is_branch.push_back(true);
    branches.push_back(std::move(b));
  }
  // Names that repeat: " (2)", " (3)", … (the first keeps its name), branches and real roots
  // alike; in parentheses so that they do not read as a body's number ("bogie2 yaw 2").
  std::map<std::string, int> seen;
  std::vector<std::string> unique(group_names.size());
  for (size_t g = 0; g < group_names.size(); ++g) {
    const int count = ++seen[group_names[g]];
    unique[g] = count == 1 ? group_names[g] : group_names[g] + " (" + std::to_string(count) + ")";
  }
  size_t next_branch = 0;
  for (size_t g = 0; g < group_names.size(); ++g)
    if (is_branch[g]) branches[next_branch++].name = unique[g];

  Branches out;
  out.name_of_root.assign(ns, std::vector<std::string>(np));
  for (int s = 0; s < ns; ++s)
    for (int p = 0; p < np; ++p) out.name_of_root[s][paths.root[s][p]] = unique[group_of_path[p]];
  std::stable_sort(branches.begin(), branches.end(), [](const HuntingBranch& a, const HuntingBranch& b) {
    return a.damping_ratio.back() < b.damping_ratio.back();
  });
  out.oscillatory = std::move(branches);
  return out;
}

}  // namespace railmodal::stability
