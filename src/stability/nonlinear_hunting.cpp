// The nonlinear critical speed: two ramp-downs, at the stated rate and at half of it, and the
// confirmation by holding the speed, bisected between the ramp's answer and a margin below it
// (docs/stability.md, "The nonlinear critical speed").
#include "railmodal/nonlinear_hunting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "stability/lateral_equations.hpp"
#include "stability/ramp_down.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

const char* to_string(NonlinearEffect effect) {
  switch (effect) {
    case NonlinearEffect::creep_saturation:
      return "creep_saturation";
    case NonlinearEffect::flange_contact:
      return "flange_contact";
  }
  return "?";
}

std::optional<NonlinearEffect> nonlinear_effect_from_string(const std::string& word) {
  for (NonlinearEffect e : {NonlinearEffect::creep_saturation, NonlinearEffect::flange_contact})
    if (word == to_string(e)) return e;
  return std::nullopt;
}

const char* to_string(NonlinearHuntingVerdict verdict) {
  switch (verdict) {
    case NonlinearHuntingVerdict::limit_cycle_dies_out:
      return "limit_cycle_dies_out";
    case NonlinearHuntingVerdict::survives_to_end_speed:
      return "survives_to_end_speed";
    case NonlinearHuntingVerdict::no_limit_cycle_at_start:
      return "no_limit_cycle_at_start";
    case NonlinearHuntingVerdict::unbounded_growth:
      return "unbounded_growth";
  }
  return "?";
}

const char* to_string(NonlinearConvergence convergence) {
  switch (convergence) {
    case NonlinearConvergence::converged:
      return "converged";
    case NonlinearConvergence::not_converged:
      return "not_converged";
    case NonlinearConvergence::not_applicable:
      return "not_applicable";
  }
  return "?";
}

std::optional<NonlinearHuntingVerdict> nonlinear_hunting_verdict_from_string(const std::string& word) {
  for (NonlinearHuntingVerdict v :
       {NonlinearHuntingVerdict::limit_cycle_dies_out, NonlinearHuntingVerdict::survives_to_end_speed,
        NonlinearHuntingVerdict::no_limit_cycle_at_start, NonlinearHuntingVerdict::unbounded_growth})
    if (word == to_string(v)) return v;
  return std::nullopt;
}

bool NonlinearHuntingOptions::is_valid(std::string* why) const {
  const auto fail = [&](const std::string& message) {
    if (why) *why = message;
    return false;
  };
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!(friction_coefficient > 0.0 && finite(friction_coefficient)))
    return fail("friction_coefficient must be positive");
  if (wheel_load && !(*wheel_load > 0.0 && finite(*wheel_load))) return fail("wheel_load must be positive");
  if (!(contact_angle >= 0.0 && contact_angle < 1.0))
    return fail("contact_angle must satisfy 0 <= contact_angle < 1 rad");
  if (!(flange_clearance >= 0.0 && finite(flange_clearance))) return fail("flange_clearance must be >= 0");
  if (!(flange_stiffness > 0.0 && finite(flange_stiffness))) return fail("flange_stiffness must be positive");
  if (!(end_speed > 0.0 && end_speed < start_speed && finite(start_speed)))
    return fail("the speeds must satisfy 0 < end_speed < start_speed");
  if (!(ramp_rate > 0.0 && finite(ramp_rate))) return fail("ramp_rate must be positive");
  if (!(disturbance != 0.0 && finite(disturbance))) return fail("disturbance must be nonzero");
  if (!(extinction_amplitude > 0.0 && finite(extinction_amplitude)))
    return fail("extinction_amplitude must be positive");
  if (!(amplitude_bound > extinction_amplitude && finite(amplitude_bound)))
    return fail("amplitude_bound must be finite and above extinction_amplitude");
  if (!(tolerance > 0.0 && finite(tolerance))) return fail("tolerance must be positive");
  if (!(hold_periods == 0 || (hold_periods >= 10 && hold_periods <= 100000)))
    return fail("hold_periods must be 0 (no confirmation) or from 10 to 100000");
  if (!(hold_margin > 0.0 && finite(hold_margin))) return fail("hold_margin must be positive");
  return true;
}

namespace {

// The confirmation: bisects on "does a cycle started on the branch survive hold_periods at this
// speed" between the ramp's answer minus a margin and the answer (widened by the margin when an end
// does not bracket), to the tolerance; then holds the lowest surviving speed twice as long.
HeldCriticalSpeed confirm_by_holding(const stability::LateralEquations& e, const NonlinearHuntingOptions& o,
                                     const RampDown& ramp, const stability::BranchStates& branch) {
  HeldCriticalSpeed held;
  const auto& curve = ramp.curve;
  // The start state for speed V: the ramp's state on the branch at V (the last half-cycle peak
  // at or above V; the branch end for any speed below it).
  const auto start_for = [&](double speed) -> const Eigen::VectorXd& {
    std::size_t i = 0;
    while (i < branch.branch_end && curve[i + 1].speed >= speed) ++i;
    return branch.states[i];
  };
  // A hold whose rate is not resolved (SpeedHold::undecided) is held again four times as long
  // (the bound on the rate falls as 1/periods, four times); still undecided, it counts as not
  // surviving for the bisection and is counted, and the answer is not converged.
  const auto hold = [&](double speed, int periods) {
    SpeedHold h = stability::hold_speed(e, o, speed, start_for(speed), ramp.watched_wheelset, periods);
    if (h.undecided) {
      held.holds.push_back(h);
      held.steps += h.steps;
      h = stability::hold_speed(e, o, speed, start_for(speed), ramp.watched_wheelset, 4 * periods);
    }
    held.holds.push_back(h);
    held.steps += h.steps;
    held.undecided_holds += h.undecided;
    return h.survives;
  };
  const double top = o.start_speed, bottom = o.end_speed;
  double high = std::min(*ramp.critical_speed, top);
  double low = std::max(high - o.hold_margin, bottom);
  bool low_dies = false;
  for (int widen = 0; !hold(high, o.hold_periods); ++widen) {
    if (widen == 4 || high >= top) return held;  // nothing survives near the ramp's answer: unconfirmed
    low = high;                                  // it died there: the bracket's lower end
    low_dies = true;
    high = std::min(high + o.hold_margin, top);
  }
  // Down from the surviving `high` by hold_margin at a time until a hold dies. A hold that
  // survives becomes `high` at once, so `high` is always the lowest surviving hold, also when the
  // widening runs out (it was left one step above it, and the answer above a surviving hold).
  for (int widen = 0; !low_dies; ++widen) {
    if (low < high) {
      if (!hold(low, o.hold_periods)) {
        low_dies = true;
        break;
      }
      high = low;
    }
    if (widen == 4 || high <= bottom) break;
    low = std::max(high - o.hold_margin, bottom);
  }
  if (low_dies) {
    while (high - low > o.tolerance) {
      const double middle = 0.5 * (high + low);
      (hold(middle, o.hold_periods) ? high : low) = middle;
    }
    held.highest_dying = low;
  }
  held.lowest_surviving = high;
  held.doubled_hold_survives = hold(high, 2 * o.hold_periods);
  return held;
}

}  // namespace

NonlinearHuntingResult solve_nonlinear_hunting(const LinearSystem& system, const NonlinearHuntingOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument("solve_nonlinear_hunting: " + why);
  NonlinearHuntingResult r;
  r.summary.analysis = "nonlinear critical speed";
  r.summary.method =
      "ramp-down of the speed, Dormand-Prince 5(4) with adaptive steps, twice (rate and half rate); confirmed by "
      "holding the speed, bisected";
  StageClock clock(&r.summary);
  const stability::LateralEquations equations(system, options);
  clock.lap("equations");
  stability::BranchStates branch;
  r.stated_rate = stability::ramp_down(equations, options, options.ramp_rate, &branch);
  clock.lap("ramp at the stated rate");
  r.halved_rate = stability::ramp_down(equations, options, options.ramp_rate / 2.0);
  clock.lap("ramp at half the rate");

  r.verdict = r.stated_rate.verdict;
  r.critical_speed = r.stated_rate.critical_speed;
  r.amplitude = r.stated_rate.amplitude;
  r.curve = r.stated_rate.curve;
  const bool both = r.stated_rate.critical_speed && r.halved_rate.critical_speed;
  r.convergence_difference = both ? std::abs(*r.stated_rate.critical_speed - *r.halved_rate.critical_speed)
                                  : std::numeric_limits<double>::infinity();
  if (both) r.richardson_critical_speed = 2.0 * *r.halved_rate.critical_speed - *r.stated_rate.critical_speed;
  const bool same_verdict = r.stated_rate.verdict == r.halved_rate.verdict;
  r.summary.checks.push_back({"critical speed change on halving the ramp rate, m/s (reported)",
                              both ? r.convergence_difference : 0.0, std::numeric_limits<double>::infinity(), true});
  if (r.verdict != NonlinearHuntingVerdict::limit_cycle_dies_out) {
    // No critical speed to converge: the verdict is the answer, if both rates give it, and if the
    // stated ramp did not end inside a collapse.
    r.collapsing_at_end_speed = r.verdict == NonlinearHuntingVerdict::survives_to_end_speed &&
                                stability::collapsing_at_end(r.stated_rate.curve);
    r.convergence = same_verdict && !r.collapsing_at_end_speed ? NonlinearConvergence::not_applicable
                                                               : NonlinearConvergence::not_converged;
  } else if (options.hold_periods == 0) {
    // No confirmation asked for: the ramp's answer stands, converged when halving the rate moves
    // it by less than the tolerance.
    r.convergence = same_verdict && r.convergence_difference <= options.tolerance ? NonlinearConvergence::converged
                                                                                  : NonlinearConvergence::not_converged;
  } else {
    r.hold = confirm_by_holding(equations, options, r.stated_rate, branch);
    clock.lap("holds of the speed");
    const HeldCriticalSpeed& h = r.hold;
    if (h.lowest_surviving) r.critical_speed = h.lowest_surviving;
    // A ramp loses the cycle near where holds do, give or take its lag (a fraction of a m/s at a
    // rate that suits it); one whose answer lies more than hold_margin above a hold whose cycle
    // survives lost the cycle before it had settled on it (the bundled scene at 5 m/s²: 257 km/h
    // against a cycle held at 239 km/h): too fast for its answer, and no lag to extrapolate.
    const auto ahead = [&](const RampDown& d) {
      return h.lowest_surviving && d.critical_speed && *d.critical_speed > *h.lowest_surviving + options.hold_margin;
    };
    r.ramp_too_fast = ahead(r.stated_rate);
    if (r.ramp_too_fast || ahead(r.halved_rate)) r.richardson_critical_speed.reset();
    const double bracket = h.lowest_surviving && h.highest_dying ? *h.lowest_surviving - *h.highest_dying
                                                                 : std::numeric_limits<double>::infinity();
    r.convergence = same_verdict && bracket <= options.tolerance && h.doubled_hold_survives && h.undecided_holds == 0
                        ? NonlinearConvergence::converged
                        : NonlinearConvergence::not_converged;
    if (h.undecided_holds > 0)
      r.summary.checks.push_back({"holds whose growth rate was not resolved, held four times as long too (count)",
                                  static_cast<double>(h.undecided_holds), 0.0, false});
    r.summary.checks.push_back(
        {"bracket of the held critical speed, m/s", bracket, options.tolerance, bracket <= options.tolerance});
    r.summary.checks.push_back({"held critical speed dies in a hold twice as long (count)",
                                h.doubled_hold_survives ? 0.0 : 1.0, 0.0, h.doubled_hold_survives});
    // Holds that bracket the answer make it (the ramp only says where to hold): the ramp's lead
    // is then reported, not failed; without the bracket it is why the answer is an estimate.
    if (r.ramp_too_fast) {
      const bool held = r.convergence == NonlinearConvergence::converged;
      r.summary.checks.push_back({held ? "stated ramp's answer above the lowest surviving hold, m/s (reported)"
                                       : "stated ramp's answer above the lowest surviving hold, m/s",
                                  *r.stated_rate.critical_speed - *h.lowest_surviving,
                                  held ? std::numeric_limits<double>::infinity() : options.hold_margin, held});
    }
  }
  r.converged = r.convergence == NonlinearConvergence::converged;
  if (r.convergence == NonlinearConvergence::not_converged && !same_verdict)
    r.summary.checks.push_back({"ramp rates with different verdicts (count)", 1.0, 0.0, false});
  if (r.collapsing_at_end_speed)
    r.summary.checks.push_back({"stated ramp collapsing at the end speed (count)", 1.0, 0.0, false});
  return r;
}

}  // namespace railmodal
