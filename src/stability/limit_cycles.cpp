// The hunting limit cycles by continuation: the lateral equations of the nonlinear hunting
// analysis as the vector field of the generic shooting and continuation (periodic_orbits,
// orbit_continuation), the watched wheelset's lateral velocity as the phase condition
// (docs/stability.md, "Continuation of the limit cycles").
#include "railmodal/limit_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "stability/lateral_equations.hpp"
#include "stability/orbit_continuation.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

const char* to_string(LimitCycleBranchKind kind) {
  switch (kind) {
    case LimitCycleBranchKind::subcritical:
      return "subcritical";
    case LimitCycleBranchKind::supercritical:
      return "supercritical";
    case LimitCycleBranchKind::no_hopf_point:
      return "no_hopf_point";
    case LimitCycleBranchKind::undetermined:
      return "undetermined";
    case LimitCycleBranchKind::neutral:
      return "neutral";
  }
  return "?";
}

std::optional<LimitCycleBranchKind> limit_cycle_branch_kind_from_string(const std::string& word) {
  for (LimitCycleBranchKind k : {LimitCycleBranchKind::subcritical, LimitCycleBranchKind::supercritical,
                                 LimitCycleBranchKind::no_hopf_point, LimitCycleBranchKind::undetermined,
                                 LimitCycleBranchKind::neutral})
    if (word == to_string(k)) return k;
  return std::nullopt;
}

const char* to_string(ContinuationEnd end) {
  switch (end) {
    case ContinuationEnd::amplitude_reached:
      return "amplitude_reached";
    case ContinuationEnd::speed_range_left:
      return "speed_range_left";
    case ContinuationEnd::point_limit:
      return "point_limit";
    case ContinuationEnd::newton_failed:
      return "newton_failed";
    case ContinuationEnd::no_hopf_point:
      return "no_hopf_point";
  }
  return "?";
}

std::optional<ContinuationEnd> continuation_end_from_string(const std::string& word) {
  for (ContinuationEnd e : {ContinuationEnd::amplitude_reached, ContinuationEnd::speed_range_left,
                            ContinuationEnd::point_limit, ContinuationEnd::newton_failed,
                            ContinuationEnd::no_hopf_point})
    if (word == to_string(e)) return e;
  return std::nullopt;
}

bool LimitCycleOptions::is_valid(std::string* why) const {
  const auto fail = [&](const std::string& message) {
    if (why) *why = message;
    return false;
  };
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!(start_amplitude > 0.0 && start_amplitude < max_amplitude && finite(max_amplitude)))
    return fail("the amplitudes must satisfy 0 < start_amplitude < max_amplitude");
  if (!(max_points >= 3 && max_points <= 100000)) return fail("max_points must be from 3 to 100000");
  if (!(steps_per_period >= 50 && steps_per_period <= 1000000))
    return fail("steps_per_period must be from 50 to 1000000");
  if (!(newton_tolerance > 0.0 && finite(newton_tolerance))) return fail("newton_tolerance must be positive");
  if (!(amplitude_unit > 0.0 && finite(amplitude_unit))) return fail("amplitude_unit must be positive");
  if (!(speed_unit > 0.0 && finite(speed_unit))) return fail("speed_unit must be positive");
  if (!(max_step >= 0.1 && finite(max_step))) return fail("max_step must be at least 0.1 (the first step)");
  return true;
}

namespace {

// A branch whose speed never departs from the Hopf speed by more than this fraction is neutral:
// the Hopf speed is bisected to 1e-12 and the orbits' speeds converge to ~1e-11; a nonlinear
// branch departs by 1e-5 already at 0.1 mm (the bundled scene: 2e-3 m/s of 66).
constexpr double kNeutral = 1e-8;

LimitCycleBranchPoint point_of(const stability::Orbit& o) {
  return {o.parameter, o.amplitude, o.period, o.stable, o.largest_multiplier, o.residual};
}

ContinuationEnd end_of(stability::BranchEnd e) {
  switch (e) {
    case stability::BranchEnd::amplitude_reached:
      return ContinuationEnd::amplitude_reached;
    case stability::BranchEnd::parameter_range_left:
      return ContinuationEnd::speed_range_left;
    case stability::BranchEnd::point_limit:
      return ContinuationEnd::point_limit;
    case stability::BranchEnd::newton_failed:
      return ContinuationEnd::newton_failed;
  }
  return ContinuationEnd::newton_failed;
}

// The wheelset whose axle centre moves most in the Hopf mode: the one hunting is watched on.
int watched_wheelset(const stability::LateralEquations& e, const Eigen::VectorXcd& mode) {
  int watched = 0;
  double most = -1.0;
  for (std::size_t k = 0; k < e.wheelsets().size(); ++k) {
    const stability::WheelsetContact& w = e.wheelsets()[k];
    const double y = std::abs(mode[w.lateral] + w.lever * mode[w.yaw]);
    if (y > most) {
      most = y;
      watched = static_cast<int>(k);
    }
  }
  return watched;
}

}  // namespace

LimitCycleBranch continue_limit_cycles(const LinearSystem& system, const NonlinearHuntingOptions& hunting,
                                       const LimitCycleOptions& options) {
  std::string why;
  if (!hunting.is_valid(&why)) throw std::invalid_argument("continue_limit_cycles: " + why);
  if (!options.is_valid(&why)) throw std::invalid_argument("continue_limit_cycles: " + why);
  LimitCycleBranch b;
  b.summary.analysis = "hunting limit cycles by continuation";
  b.summary.method =
      "shooting (fixed-step Dormand-Prince 5(4), Newton with a finite-difference monodromy matrix), "
      "pseudo-arclength continuation in speed from the Hopf point, folds refined";
  StageClock clock(&b.summary);
  const stability::LateralEquations e(system, hunting);
  stability::OrbitProblem problem;
  problem.field = [&e](double speed, const Eigen::VectorXd& x, Eigen::VectorXd* dx) { e.derivative(speed, x, dx); };
  const int n = e.size();
  const std::optional<stability::HopfPoint> hopf =
      stability::find_hopf(problem.field, n, hunting.end_speed, hunting.start_speed);
  clock.lap("Hopf point");
  if (!hopf) {
    b.summary.checks.push_back({"Hopf points in the speed range (count)", 0.0, 0.0, true});
    return b;
  }
  b.hopf_speed = hopf->parameter;
  b.hopf_frequency = hopf->frequency / (2.0 * 3.14159265358979323846);
  b.watched_wheelset = watched_wheelset(e, hopf->vector);
  const stability::WheelsetContact& w = e.wheelsets()[static_cast<std::size_t>(b.watched_wheelset)];
  problem.amplitude = Eigen::RowVectorXd::Zero(n);
  problem.amplitude[w.lateral] += 1.0;
  problem.amplitude[w.yaw] += w.lever;
  // The phase condition: the axle centre's lateral velocity is zero at t = 0 (a peak of y).
  problem.phase = Eigen::RowVectorXd::Zero(n);
  problem.phase[e.dofs() + w.lateral] += 1.0;
  problem.phase[e.dofs() + w.yaw] += w.lever;
  // Each state's size per metre of the watched y in the Hopf mode (floored at a thousandth of
  // the largest, so a state the mode hardly moves still has a sensible difference step).
  const Eigen::VectorXd size = hopf->vector.cwiseAbs();
  problem.scale = size.cwiseMax(1e-3 * size.maxCoeff()) / std::abs(problem.amplitude.dot(hopf->vector));
  problem.amplitude_scale = options.amplitude_unit;
  problem.parameter_scale = options.speed_unit;
  problem.steps_per_period = options.steps_per_period;
  problem.newton_tolerance = options.newton_tolerance;
  stability::ContinuationSettings settings;
  settings.start_amplitude = options.start_amplitude;
  settings.max_amplitude = options.max_amplitude;
  settings.parameter_low = hunting.end_speed;
  settings.parameter_high = hunting.start_speed;
  settings.max_points = options.max_points;
  settings.max_step = options.max_step;
  settings.progress = options.progress;
  const stability::OrbitBranch branch = stability::continue_from_hopf(problem, *hopf, settings);
  clock.lap("continuation");
  b.end = end_of(branch.end);
  b.failure = branch.failure;
  b.flows = branch.flows;
  for (const stability::Orbit& o : branch.orbits) b.points.push_back(point_of(o));
  for (const stability::Orbit& o : branch.folds) b.folds.push_back(point_of(o));
  double departure = 0.0;  // the largest |V − V_Hopf| of the branch
  for (const LimitCycleBranchPoint& p : b.points) departure = std::max(departure, std::abs(p.speed - *b.hopf_speed));
  if (b.points.size() < 2)
    b.kind = LimitCycleBranchKind::undetermined;
  else if (departure <= kNeutral * *b.hopf_speed)
    b.kind = LimitCycleBranchKind::neutral;
  else
    b.kind = b.points[1].speed < *b.hopf_speed ? LimitCycleBranchKind::subcritical
                                                : LimitCycleBranchKind::supercritical;
  // The nonlinear critical speed is the fold where the unstable cycles meet the stable ones, not
  // the first turn of the speed: a subcritical branch may wiggle while still unstable on both sides
  // (the Manchester coach's turns at 351.89 and 351.92 km/h, 60 km/h above its true fold).
  if (b.kind == LimitCycleBranchKind::subcritical) {
    std::vector<double> speeds;
    std::vector<bool> stable;
    for (const stability::Orbit& o : branch.orbits) {
      speeds.push_back(o.parameter);
      stable.push_back(o.stable);
    }
    if (const std::optional<std::size_t> m = stability::lowest_exchange_turn(speeds, stable))
      for (std::size_t i = 0; i < branch.fold_orbits.size(); ++i)
        if (branch.fold_orbits[i] == *m) b.fold = b.folds[i];
  }
  // A figure, not a check: continue_from_hopf keeps only converged orbits, so every residual is
  // within newton_tolerance by construction and a bound on it could never fail (limit +∞:
  // reported, not bounded).
  double largest = 0.0;
  for (const LimitCycleBranchPoint& p : b.points) largest = std::max(largest, p.residual);
  b.summary.checks.push_back(
      {"largest Newton residual of the branch", largest, std::numeric_limits<double>::infinity(), true});
  b.summary.checks.push_back({"corrector failures ending the branch (count)",
                              b.end == ContinuationEnd::newton_failed ? 1.0 : 0.0, 0.0,
                              b.end != ContinuationEnd::newton_failed});
  return b;
}

}  // namespace railmodal
