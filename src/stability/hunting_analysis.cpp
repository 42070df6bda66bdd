// The hunting-stability analysis: eigenvalues over the speed grid and their tracking
// (solve_grid), the branches, the unstable intervals and the critical speed
// (stability_over_speed), the threshold speed (threshold_crossing), the conicity curve and the
// summary, each a function of its own.
//
// Stability is judged by the least-damped root's ζ = −Re λ/|λ| over all roots (branches,
// real roots, the series dampers' roots), not by Re λ: as V → 0 the creep damping C_c/V
// grows without bound and every root of the wheelsets' motions either runs off to −∞
// (ζ = 1) or slows down with V (the kinematic motion, whose eigenvalue scales with V), so
// Re λ → 0 without saying whether the motion decays per cycle; ζ keeps a limit.
#include "stability/hunting_analysis.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "railmodal/errors.hpp"
#include "shortest_text.hpp"
#include "stability/branch_naming.hpp"
#include "stability/branches.hpp"
#include "stability/damping_search.hpp"
#include "stability/first_order_system.hpp"
#include "stability/parallel_for.hpp"
#include "stability/root_tracking.hpp"
#include "stability/speed_scan.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal::stability {

namespace {

constexpr double kTwoPi = 6.283185307179586476925;
// An eigen-solve whose backward error exceeds this is not trusted (Hessenberg QR reaches
// about n·ε ≈ 1e-14 on a balanced matrix; 1e-8 is six orders above).
constexpr double kMaxResidual = 1e-8;

std::vector<double> speed_grid(const HuntingOptions& options) {
  std::vector<double> v(options.speed_count);
  const double step = (options.max_speed - options.min_speed) / (options.speed_count - 1);
  for (int s = 0; s < options.speed_count; ++s) v[s] = options.min_speed + step * s;
  v.back() = options.max_speed;
  return v;
}

double shortest_wavelength(const ContactMatrices& contact) {
  double wavelength = std::numeric_limits<double>::infinity();
  for (const ResolvedContact& c : contact.wheelsets) wavelength = std::min(wavelength, c.klingel_wavelength);
  return wavelength;
}

// The kinematic wavelength of a rigid bogie, Λ_b = Λ·√(1 + ā²f22/(l0²f11)) (docs/stability.md,
// "The equations of motion": no net lateral creep force and no net yaw moment on its wheelsets
// with a common yaw; Rocard's factor √(1 + (2a/s)²) when f11 = f22 and two axles at ±a: the
// digest bogie-wagons-forced-and-hunting, §2.1, p. 217). With N axles at x_i the same balance
// gives ā² = Σ(x_i − x̄)²/N (WheelsetBogie::axle_spread): a² for two, 2a²/3 for three at −a, 0,
// a. The contact of the bogie's first wheelset; infinite when there is none.
double bogie_wavelength(const LinearSystem& system, const ContactMatrices& contact, const WheelsetBogie& g) {
  for (const ResolvedContact& c : contact.wheelsets) {
    if (c.body != system.vehicle.bodies[g.wheelsets.front()].name) continue;
    const double a = g.axle_spread, l0 = c.contact_half_spacing;
    if (c.creep.f11 > 0.0 && l0 > 0.0)
      return c.klingel_wavelength * std::sqrt(1.0 + a * a * c.creep.f22 / (l0 * l0 * c.creep.f11));
  }
  return std::numeric_limits<double>::infinity();
}

// The body carrying two or more wheelsets whose wheelsets move most in a root's shape (the sum
// of |shape|² over their degrees of freedom, the shape mass-weighted as root_name takes it; the
// first on a tie), or null when no body carries two.
std::optional<WheelsetBogie> moving_bogie(const LinearSystem& system, const Eigen::VectorXcd& shape) {
  std::optional<WheelsetBogie> out;
  double most = -1.0;
  for (const WheelsetBogie& g : wheelset_carriers(system.vehicle)) {
    double energy = 0.0;
    for (int i = 0; i < system.size(); ++i)
      if (std::find(g.wheelsets.begin(), g.wheelsets.end(), system.dofs[i].body) != g.wheelsets.end())
        energy += std::norm(shape(i));
    if (energy > most) most = energy, out = g;
  }
  return out;
}

double klingel_frequency(double speed, double wavelength) {
  return std::isfinite(wavelength) && wavelength > 0.0 ? speed / wavelength : 0.0;
}

// The least-damped ζ at any speed: eigenvalues only.
struct ZetaFunction {
  const FirstOrderSystem& system;
  double operator()(double speed, bool raw = false) const {
    return least_damped(solve_at_speed(system, speed, false).values, raw).zeta;
  }
};

// What the grid scan of one conicity gives.
struct Scan {
  HuntingVerdict verdict = HuntingVerdict::stable_throughout;
  std::vector<ScannedInterval> intervals;
  int evaluations = 0;
};

Scan scan(const std::vector<double>& speeds, const std::vector<double>& zeta, const FirstOrderSystem& system,
          double relative_tolerance) {
  Scan out;
  out.intervals = unstable_intervals(speeds, zeta, ZetaFunction{system}, relative_tolerance, &out.evaluations);
  if (zeta[0] < 0.0)
    out.verdict = HuntingVerdict::unstable_at_lowest_speed;
  else if (!out.intervals.empty())
    out.verdict = HuntingVerdict::critical_speed_in_range;
  return out;
}

// The critical speed of a scan that has one: the first interval's lower end, with the
// hunting frequency of the least-damped root there (one more eigen-solve).
HuntingCriticalSpeed critical_speed(const LinearSystem& vehicle, const Scan& scan, const FirstOrderSystem& system,
                                    const ContactMatrices& contact) {
  const ScannedInterval& first = scan.intervals.front();
  HuntingCriticalSpeed c;
  c.speed = first.from;
  const SpeedRoots roots = solve_at_speed(system, c.speed, true);
  const LeastDamped at = least_damped(roots.values);
  c.frequency_hz = at.root >= 0 ? std::abs(roots.values(at.root).imag()) / kTwoPi : 0.0;
  c.motion = root_name(vehicle, roots.shapes.col(std::max(at.root, 0)));
  c.klingel_frequency_hz = klingel_frequency(c.speed, shortest_wavelength(contact));
  // V/Λ_b of the bogie that carries the hunting: whose wheelsets move most in the unstable mode.
  if (const std::optional<WheelsetBogie> g = moving_bogie(vehicle, roots.shapes.col(std::max(at.root, 0)))) {
    c.bogie_frequency_hz = klingel_frequency(c.speed, bogie_wavelength(vehicle, contact, *g));
    if (c.bogie_frequency_hz > 0.0) c.bogie = vehicle.vehicle.bodies[static_cast<size_t>(g->body)].name;
  }
  c.evaluations = first.from_evaluations + 1;
  return c;
}

ConicityPoint conicity_point(const LinearSystem& system, double conicity, const ContactMatrices& contact,
                             const std::vector<double>& speeds, const std::vector<double>& zeta,
                             const HuntingOptions& options) {
  const FirstOrderSystem fos(system, contact);
  ConicityPoint point;
  point.conicity = conicity;
  const Scan s = scan(speeds, zeta, fos, options.relative_tolerance);
  point.verdict = s.verdict;
  if (s.verdict == HuntingVerdict::critical_speed_in_range) {
    point.critical = critical_speed(system, s, fos, contact);
    // Named where it goes unstable (no tracking over this conicity's grid).
    point.critical->branch = point.critical->motion;
  }
  return point;
}

std::vector<ConicityPoint> conicity_curve(const LinearSystem& system, const ContactSource& contact,
                                          const std::vector<double>& speeds, const HuntingOptions& options) {
  const int nc = static_cast<int>(options.conicities.size()), ns = static_cast<int>(speeds.size());
  std::vector<ContactMatrices> contacts;
  for (double c : options.conicities) contacts.push_back(contact(c));  // on this thread (see the header)
  std::vector<FirstOrderSystem> systems;
  for (const ContactMatrices& c : contacts) systems.emplace_back(system, c);
  std::vector<std::vector<double>> zeta(nc, std::vector<double>(ns));
  parallel_for(nc * ns, options.threads,
               [&](int k) { zeta[k / ns][k % ns] = ZetaFunction{systems[k / ns]}(speeds[k % ns]); });
  std::vector<ConicityPoint> curve(nc);
  parallel_for(nc, options.threads, [&](int c) {
    curve[c] = conicity_point(system, options.conicities[c], contacts[c], speeds, zeta[c], options);
  });
  return curve;
}

// The roots over the speed grid, tracked, with eigenvectors where the tracking needs them.
struct SolvedGrid {
  std::vector<SpeedRoots> roots;
  RootPaths paths;
  int with_shapes = 0;    // speeds solved with eigenvectors
  double residual = 0.0;  // the largest relative residual of those solves
};

// Eigenvalues at every speed; shapes only where the tracking needs them (the first speed, which
// names the branches, and both ends of every step the eigenvalues cannot match alone). On a
// coarse grid (fewer than 64 speeds) the steps are too long for the eigenvalues alone to decide
// most of them: shapes everywhere at once.
SolvedGrid solve_grid(const FirstOrderSystem& fos, const std::vector<double>& speeds, int threads, StageClock* clock) {
  const int ns = static_cast<int>(speeds.size());
  const bool shapes_everywhere = ns < 64;
  SolvedGrid grid;
  grid.roots.resize(ns);
  parallel_for(ns, threads, [&](int s) { grid.roots[s] = solve_at_speed(fos, speeds[s], shapes_everywhere); });
  clock->lap("eigenvalues over the speed grid");
  std::vector<int> missing, with_shapes;
  if (shapes_everywhere)
    for (int s = 0; s < ns; ++s) with_shapes.push_back(s);
  else
    missing.push_back(0);
  grid.paths = track_roots(grid.roots, &missing);
  while (!missing.empty()) {
    // The solve with vectors replaces the one without, values and all: Eigen's values agree
    // either way in practice (its real Schur form updates the whole of T), but were they to
    // differ in the last bits, the values that go with the vectors are the consistent pair, and
    // the tracking below runs again on them.
    parallel_for(static_cast<int>(missing.size()), threads,
                 [&](int k) { grid.roots[missing[k]] = solve_at_speed(fos, speeds[missing[k]], true); });
    with_shapes.insert(with_shapes.end(), missing.begin(), missing.end());
    missing.clear();
    grid.paths = track_roots(grid.roots, &missing);
    // A symmetric vehicle's nearly repeated roots (front and rear wheelsets, the two bogies)
    // can leave the eigenvalues undecided at most speeds: then shapes everywhere at once, in
    // one parallel batch, rather than pass after pass.
    if (4 * (missing.size() + with_shapes.size()) > static_cast<size_t>(ns)) {
      missing.clear();
      for (int s = 0; s < ns; ++s)
        if (grid.roots[s].shapes.size() == 0) missing.push_back(s);
    }
  }
  grid.with_shapes = static_cast<int>(with_shapes.size());
  std::sort(with_shapes.begin(), with_shapes.end());
  for (int s : with_shapes) {
    const SpeedRoots& r = grid.roots[s];
    if (!(r.residual <= kMaxResidual))
      throw NumericalError("hunting stability: the eigen-solve at " + shortest_text(r.speed, 6) +
                           " m/s has a relative residual of " + shortest_text(r.residual, 3) + " (limit " +
                           shortest_text(kMaxResidual, 3) + ")");
    grid.residual = std::max(grid.residual, r.residual);
  }
  return grid;
}

// ζ of one branch between grid speeds s − 1 and s: the root (upper half) nearest to the branch's
// eigenvalue interpolated linearly between the two grid speeds. Within a grid step a branch
// moves little against its distance to the others (the tracking matched it by eigenvalues or
// shapes over the whole step), so the nearest root is the branch's. `raw` as in ZetaAt.
double branch_zeta(const FirstOrderSystem& fos, const HuntingBranch& b, const std::vector<double>& speeds, int s,
                   double speed, bool raw = true) {
  const double t = (speed - speeds[s - 1]) / (speeds[s] - speeds[s - 1]);
  const std::complex<double> guess = (1.0 - t) * b.eigenvalues[s - 1] + t * b.eigenvalues[s];
  const Eigen::VectorXcd values = solve_at_speed(fos, speed, false).values;
  int nearest = 0;
  for (int i = 1; i < values.size(); ++i)
    if (std::abs(values(i) - guess) < std::abs(values(nearest) - guess)) nearest = i;
  const std::complex<double> upper = values(nearest).imag() < 0.0 ? std::conj(values(nearest)) : values(nearest);
  return root_damping(upper, root_scale(values), raw).zeta;
}

// A branch's name without what tells it from its namesakes: " (2)", " (3)", … and " (kinematic)".
std::string base_name(std::string name) {
  for (bool cut = true; cut;) {
    cut = false;
    const size_t open = name.rfind(" (");
    if (open == std::string::npos || name.back() != ')') break;
    const std::string inside = name.substr(open + 2, name.size() - open - 3);
    if (inside == "kinematic" || (!inside.empty() && std::all_of(inside.begin(), inside.end(), [](char c) {
                                    return c >= '0' && c <= '9';
                                  }))) {
      name.erase(open);
      cut = true;
    }
  }
  return name;
}

// One branch's unstable intervals: where its own ζ is below 0 on the grid, each end refined on
// that branch (branch_zeta in the grid step that holds the speed).
std::vector<ScannedInterval> branch_intervals(const FirstOrderSystem& fos, const HuntingBranch& b,
                                              const std::vector<double>& speeds, double relative_tolerance,
                                              int* evaluations) {
  const auto zeta_at = [&](double v, bool raw) {
    const auto above = std::upper_bound(speeds.begin(), speeds.end(), v);
    const int s = std::clamp(static_cast<int>(above - speeds.begin()), 1, static_cast<int>(speeds.size()) - 1);
    return branch_zeta(fos, b, speeds, s, v, raw);
  };
  return unstable_intervals(speeds, b.damping_ratio, zeta_at, relative_tolerance, evaluations);
}

// The divergences: for each group of roots real at every speed (no branch), the runs of grid
// speeds where one of them is positive (ζ < 0 and not rigid-body), named after the group. A real
// root changes sign only through λ = 0, and λ = 0 is a root of the state matrix exactly when the
// stiffness K is singular (A·x = 0 forces the velocities, then the series dampers' states, to 0,
// leaving K·x = 0): K does not depend on the speed, so a divergence holds at every speed of the
// range or at none, and its ends are the grid's. Every group is looked at, not only the least
// damped root: with two divergent groups (ζ = −1 both) the least-damped search names only one.
std::vector<UnstableInterval> divergences(const SolvedGrid& grid, const Branches& branches,
                                          const std::vector<HuntingBranch>& all, const std::vector<double>& speeds) {
  std::vector<std::string> groups;
  for (const std::vector<std::string>& names : branches.name_of_root)
    for (const std::string& name : names)
      if (std::none_of(all.begin(), all.end(), [&](const HuntingBranch& b) { return b.name == name; }) &&
          std::find(groups.begin(), groups.end(), name) == groups.end())
        groups.push_back(name);
  std::vector<UnstableInterval> out;
  const size_t ns = speeds.size();
  for (const std::string& group : groups) {
    size_t first = ns;  // where the current run of divergent speeds began; ns: none open
    for (size_t s = 0; s <= ns; ++s) {
      bool diverges = false;
      if (s < ns) {
        const Eigen::VectorXcd& values = grid.roots[s].values;
        const double scale = root_scale(values);
        for (Eigen::Index i = 0; i < values.size(); ++i) {
          if (branches.name_of_root[s][static_cast<size_t>(i)] != group) continue;
          const RootDamping d = root_damping(values(i), scale);
          diverges = diverges || (!d.rigid && d.zeta < 0.0);
        }
      }
      if (diverges && first == ns) first = s;
      if (!diverges && first != ns) {
        out.push_back({speeds[first], speeds[s - 1], first == 0, s == ns, group, true});
        first = ns;
      }
    }
  }
  return out;
}

// The verdict, the critical speed (the least-damped root's first crossing) and the unstable
// intervals: each oscillatory branch's own (docs/stability.md: every unstable interval, its ends
// where ζ of its branch crosses 0, so that a branch going unstable while another already is
// still shows: the coach's second hunting branch, user audit 2026-11-27b, 1.3), and every
// divergence of a real root (divergences), named after its group. Returns the eigen-solves the
// refinements took.
int stability_over_speed(const LinearSystem& system, const FirstOrderSystem& fos, const SolvedGrid& grid,
                         const Branches& branches, const std::vector<double>& zeta, const ContactMatrices& contact,
                         const HuntingOptions& options, HuntingResult* result) {
  const Scan own = scan(result->speeds, zeta, fos, options.relative_tolerance);
  int evaluations = own.evaluations;
  result->verdict = own.verdict;
  struct Listed {
    UnstableInterval interval;
    size_t branch;  // its place in result->branches; real roots after every branch
  };
  std::vector<Listed> listed;
  const auto named = [](const ScannedInterval& i, const std::string& name) {
    return UnstableInterval{i.from, i.to, i.from_lowest_speed, i.to_highest_speed, name};
  };
  const std::vector<HuntingBranch>& all = result->branches;
  for (size_t k = 0; k < all.size(); ++k)
    for (const ScannedInterval& i : branch_intervals(fos, all[k], result->speeds, options.relative_tolerance, &evaluations))
      listed.push_back({named(i, all[k].name), k});
  for (const UnstableInterval& i : divergences(grid, branches, all, result->speeds)) listed.push_back({i, all.size()});
  std::string critical_branch;
  if (!own.intervals.empty()) {
    const size_t s = own.intervals.front().grid_index;
    const int at = least_damped(grid.roots[s].values).root;
    if (at >= 0) critical_branch = branches.name_of_root[s][static_cast<size_t>(at)];
  }
  std::stable_sort(listed.begin(), listed.end(), [](const Listed& a, const Listed& b) {
    return a.interval.from != b.interval.from ? a.interval.from < b.interval.from : a.branch < b.branch;
  });
  for (const Listed& l : listed) result->unstable_intervals.push_back(l.interval);
  if (result->verdict == HuntingVerdict::critical_speed_in_range) {
    result->critical = critical_speed(system, own, fos, contact);
    result->critical->branch = critical_branch;
    // The motion is named as branches are; where that is another branch's name, it would read as
    // that branch (user audit 2026-11-27b, 1.4: "body lateral/roll" on branch "body yaw/lateral
    // (kinematic)", beside a stable branch of that name).
    std::string& motion = result->critical->motion;
    const bool another = std::any_of(all.begin(), all.end(), [&](const HuntingBranch& b) {
      return b.name != critical_branch && base_name(b.name) == base_name(motion);
    });
    if (another) motion += " (shape at the critical speed)";
    evaluations += 1;
  }
  return evaluations;
}

// The threshold speed (HuntingResult::threshold_speed): the lowest downward crossing of the
// threshold by a branch that was above it at a lower grid speed. Returns the eigen-solves.
int threshold_crossing(const FirstOrderSystem& fos, double threshold, double relative_tolerance,
                       HuntingResult* result) {
  const std::vector<double>& speeds = result->speeds;
  const int ns = static_cast<int>(speeds.size());
  std::vector<std::pair<double, std::string>> below;
  int first_step = ns;  // the earliest grid step in which some branch crosses downwards
  std::vector<const HuntingBranch*> crossing;
  for (const HuntingBranch& b : result->branches) {
    const std::vector<double>& zeta = b.damping_ratio;
    if (zeta[0] <= threshold) below.push_back({zeta[0], b.name});
    bool was_above = false;
    for (int s = 0; s < ns && s <= first_step; ++s) {
      if (was_above && zeta[s] <= threshold) {
        if (s < first_step) first_step = s, crossing.clear();
        crossing.push_back(&b);
        break;
      }
      was_above = was_above || zeta[s] > threshold;
    }
  }
  std::stable_sort(below.begin(), below.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [zeta, name] : below) result->below_threshold_at_lowest_speed.push_back(name);
  int evaluations = 0;
  for (const HuntingBranch* b : crossing) {
    const int s = first_step;
    const auto f = [&](double v) { return branch_zeta(fos, *b, speeds, s, v) - threshold; };
    const BracketedRoot root = bracketed_root(f, speeds[s - 1], speeds[s], b->damping_ratio[s - 1] - threshold,
                                              b->damping_ratio[s] - threshold, relative_tolerance);
    evaluations += root.evaluations;
    if (!result->threshold_speed || root.x < *result->threshold_speed) {
      result->threshold_speed = root.x;
      result->threshold_branch = b->name;
    }
  }
  return evaluations;
}

// The most roots left out as rigid-body at any grid speed.
int neutral_roots(const std::vector<SpeedRoots>& roots) {
  int most = 0;
  for (const SpeedRoots& r : roots) {
    const double scale = root_scale(r.values);
    int count = 0;
    for (int i = 0; i < r.values.size(); ++i) count += root_damping(r.values(i), scale).rigid ? 1 : 0;
    most = std::max(most, count);
  }
  return most;
}

// 1 − `threshold` as the decimal the user means: 0.8 is stored as 0.80000000000000004441, and
// 1 − that is exactly 0.19999999999999995559, one ulp below the double nearest 0.2, which reports
// printed as 0.19999999999999996. Rounded to 15 significant digits (a double's 15.95 round-trip
// exactly from decimal) and read back, it is 0.2; the check's verdict compares the MAC with the
// threshold itself, not with this.
double complement_as_given(double threshold) {
  const std::string text = shortest_text(1.0 - threshold, 15);
  double value = 1.0 - threshold;
  std::from_chars(text.data(), text.data() + text.size(), value);  // locale-free
  return value;
}

void summarise(const SolvedGrid& grid, const std::vector<double>& zeta, int evaluations, const HuntingOptions& options,
               HuntingResult* result) {
  double continuity = 1.0;
  for (const HuntingBranch& b : result->branches)
    for (double c : b.continuity) continuity = std::min(continuity, c);
  AnalysisSummary& summary = result->summary;
  summary.analysis = "hunting stability";
  summary.method =
      "QR of the balanced first-order state matrix at each speed (Eigen), roots tracked by MAC and "
      "eigenvalue continuity (Hungarian assignment), least-damped ζ refined by Brent's method";
  // No thread count in the method: the answer is the same whatever it is, and the reports write
  // the method, so that two runs' outputs differed where their results did not.
  const double inf = std::numeric_limits<double>::infinity();
  summary.checks.push_back({"max relative eigen residual", grid.residual, kMaxResidual, grid.residual <= kMaxResidual});
  summary.checks.push_back({"1 − minimum branch continuity (MAC)", 1.0 - continuity, complement_as_given(options.continuity_threshold),
                            continuity >= options.continuity_threshold});
  summary.checks.push_back({"least-damped ζ at the lowest speed", zeta.front(), inf, true});
  summary.checks.push_back({"refinement evaluations (eigenvalues only)", static_cast<double>(evaluations), inf, true});
  summary.checks.push_back(
      {"speeds solved with eigenvectors (for the tracking)", static_cast<double>(grid.with_shapes), inf, true});
  summary.checks.push_back(
      {"rigid-body roots left out of the search (neutral)", static_cast<double>(result->neutral_roots), inf, true});
}

}  // namespace

HuntingResult hunting_analysis(const LinearSystem& system, const ContactSource& contact,
                               const HuntingOptions& options) {
  HuntingResult result;
  StageClock clock(&result.summary);
  const ContactMatrices own = contact(std::nullopt);
  result.contacts = own.wheelsets;
  clock.lap("contact matrices");
  const FirstOrderSystem fos(system, own);
  clock.lap("factor M");

  result.speeds = speed_grid(options);
  for (const Dof& d : system.dofs) result.dofs.push_back(d.label);
  const SolvedGrid grid = solve_grid(fos, result.speeds, options.threads, &clock);
  clock.lap("tracking, with eigenvectors where it needs them");

  const double wavelength = shortest_wavelength(own);
  const Branches branches = group_branches(system, grid.roots, grid.paths, wavelength, options.continuity_threshold);
  result.branches = branches.oscillatory;
  result.neutral_roots = neutral_roots(grid.roots);
  clock.lap("branches and names");

  std::vector<double> zeta;
  for (const SpeedRoots& r : grid.roots) zeta.push_back(least_damped(r.values).zeta);
  int evaluations = stability_over_speed(system, fos, grid, branches, zeta, own, options, &result);
  result.damping_threshold = options.damping_threshold;
  if (options.damping_threshold)
    evaluations += threshold_crossing(fos, *options.damping_threshold, options.relative_tolerance, &result);
  clock.lap("critical speed and intervals");

  result.conicity_curve = conicity_curve(system, contact, result.speeds, options);
  clock.lap("conicity curve");
  summarise(grid, zeta, evaluations, options, &result);
  return result;
}

}  // namespace railmodal::stability
