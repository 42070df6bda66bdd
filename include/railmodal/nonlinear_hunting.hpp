// railmodal — the nonlinear critical speed: the lateral equations of a vehicle on its wheelsets
// integrated in time while the speed ramps down from a disturbed start, with the creep forces
// saturating at μN and a flange beyond its clearance; the lowest speed at which the hunting limit
// cycle survives, its amplitude, and the amplitude against speed (docs/stability.md, "The
// nonlinear critical speed").
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Vehicle v;  // one wheelset on lateral and yaw springs to a fixed frame
//     v.name = "wheelset on springs";
//     railmodal::Body b;
//     b.name = "wheelset";
//     b.mass = 1500.0;
//     b.inertia = {700.0, 800.0, 800.0};
//     b.held = {railmodal::Motion::bounce, railmodal::Motion::roll, railmodal::Motion::pitch};
//     v.bodies.push_back(b);
//     for (double y : {-1.0, 1.0}) {
//       railmodal::Element e;
//       e.name = y > 0 ? "left" : "right";
//       e.upper = "wheelset";
//       e.point = {0.0, y, 0.0};
//       e.lateral_stages = {{"coil", 5e5, 1}};
//       e.longitudinal_stages = {{"coil", 1e6, 1}};
//       v.elements.push_back(e);
//     }
//     railmodal::Wheelset w;
//     w.body = "wheelset";
//     w.spin_inertia = 100.0;
//     w.contact.rolling_radius = 0.46;
//     w.contact.contact_half_spacing = 0.75;
//     w.contact.conicity = 0.15;
//     w.contact.creep = railmodal::CreepCoefficients{1.0e7, 0.9e7, 1.0e4, 100.0};
//     v.wheelsets.push_back(w);
//
//     railmodal::NonlinearHuntingOptions options;
//     options.wheel_load = 50e3;  // N: the load the creep coefficients were sized for
//     options.start_speed = 80.0;
//     options.end_speed = 20.0;
//     auto r = railmodal::solve_nonlinear_hunting(railmodal::assemble(v, railmodal::DofSet::lateral), options);
//     std::cout << to_string(r.verdict) << "\n";
//     if (r.critical_speed)
//       std::cout << "a limit cycle survives down to " << *r.critical_speed * 3.6 << " km/h, amplitude "
//                 << r.amplitude * 1e3 << " mm\n";
//   }
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/summary.hpp"

namespace railmodal {

/// The nonlinearities a nonlinear hunting analysis simulates; only those named are (without
/// creep_saturation the creep law is Kalker's linear one; without flange_contact there is no
/// flange).
enum class NonlinearEffect {
  creep_saturation,  ///< Shen–Hedrick–Elkins: the resultant creep force saturates at μN
  flange_contact     ///< a stiff lateral spring beyond the flange clearance
};
const char* to_string(NonlinearEffect effect);
std::optional<NonlinearEffect> nonlinear_effect_from_string(const std::string& word);

struct NonlinearHuntingOptions {
  std::vector<NonlinearEffect> effects{NonlinearEffect::creep_saturation, NonlinearEffect::flange_contact};
  double friction_coefficient = 0.4;  ///< μ (creep_saturation), > 0
  /// Normal load on each wheel, N (creep_saturation); none: half the wheelset's axle load W.
  std::optional<double> wheel_load;
  /// δ0, rad (creep_saturation): the contact angle of the centred wheelset, whose spin ∓δ0/r0
  /// takes part of the adhesion at rest. 0: neglected (then the small-amplitude limit is exactly
  /// the linear model). ≥ 0.
  double contact_angle = 0.0;
  double flange_clearance = 0.008;  ///< m (flange_contact): the lateral play before the flange, ≥ 0
  double flange_stiffness = 1.0e7;  ///< N/m (flange_contact): the rail's lateral stiffness at the flange, > 0
  double start_speed = 100.0;       ///< m/s: where the ramp starts, with the disturbance
  double end_speed = 5.0;           ///< m/s: where it stops, 0 < end_speed < start_speed
  double ramp_rate = 0.5;           ///< m/s²: how fast the speed falls, > 0
  double disturbance = 0.005;       ///< m: every wheelset's initial lateral displacement, ≠ 0
  /// m: an oscillation whose largest wheelset amplitude is below this has died out, > 0.
  double extinction_amplitude = 1e-4;
  /// m: a lateral amplitude beyond this is unbounded growth (a law without saturation or flange
  /// above its critical speed): the run stops there with that verdict. 0.1 m is ten times any
  /// flange clearance: no wheelset on a track gets there. > extinction_amplitude.
  double amplitude_bound = 0.1;
  /// m/s: the held critical speed is bracketed to within this (docs/stability.md). 0.05 m/s
  /// (0.18 km/h) is well under the ramp's own bias (0.2–0.3 m/s at 0.5 m/s² on the wheelset on
  /// springs) and what a hold of hold_periods resolves there (the doubled hold agrees). > 0.
  double tolerance = 0.05;
  /// Periods a held speed must keep its limit cycle to count as surviving (the confirmation); the
  /// check holds the answer again for twice as long. ≥ 10; 0 skips the confirmation (the ramp's
  /// answer is then the critical speed).
  int hold_periods = 300;
  /// m/s: the confirmation bisects between the ramp's answer minus this and the answer (widening
  /// by this step, up to 4 times, when an end is not a bracket). > 0.
  double hold_margin = 1.0;
  bool is_valid(std::string* why) const;
};

enum class NonlinearHuntingVerdict {
  limit_cycle_dies_out,     ///< a limit cycle was established and died out during the ramp
  survives_to_end_speed,    ///< the oscillation still lives at the end speed: the critical speed is below it
  no_limit_cycle_at_start,  ///< the disturbance decayed at once: no limit cycle at the start speed
  /// The amplitude passed options.amplitude_bound: the oscillation grows without bound (a law
  /// without saturation or flange above its critical speed); the run stopped there.
  unbounded_growth
};
const char* to_string(NonlinearHuntingVerdict verdict);
std::optional<NonlinearHuntingVerdict> nonlinear_hunting_verdict_from_string(const std::string& word);

/// One half cycle of the watched wheelset's lateral motion during the ramp.
struct LimitCyclePoint {
  double speed = 0.0;      ///< m/s at the half cycle's peak
  double amplitude = 0.0;  ///< m: the largest |y| of the axle centre over the half cycle
};

/// What one ramp-down found.
struct RampDown {
  double ramp_rate = 0.0;  ///< m/s²
  NonlinearHuntingVerdict verdict = NonlinearHuntingVerdict::no_limit_cycle_at_start;
  /// Where the limit cycle was lost, only with limit_cycle_dies_out: the branch ends at the last
  /// half cycle whose amplitude fell by less than 0.5% from the one before, after which it falls
  /// faster every half cycle until it dies out; the decay per half cycle of the collapse's first
  /// half cycles, fitted against speed and extrapolated to zero, gives the speed where the decay
  /// began (the speed of the branch end itself when the fit cannot, docs/stability.md).
  std::optional<double> critical_speed;
  double amplitude = 0.0;              ///< m: the amplitude at the branch end
  std::vector<LimitCyclePoint> curve;  ///< every half cycle until the oscillation died out
  int steps = 0;                       ///< accepted Runge–Kutta steps
  /// Index (into Vehicle::wheelsets) of the wheelset whose amplitude the curve is: the one with
  /// the largest lateral amplitudes over the ramp (Σ of its half-cycle amplitudes), so hunting
  /// carried by any wheelset is seen.
  int watched_wheelset = 0;
};

/// One held speed of the confirmation: the ramp's state on the branch, integrated at a fixed speed.
struct SpeedHold {
  double speed = 0.0;            ///< m/s
  /// The cycle survives: it grew past the amplitude bound, or held all the periods without falling
  /// below half the start's amplitude and its amplitude's growth rate over the hold's second half
  /// is resolved at or above −1e-4 per period (rate_per_period − rate_error ≥ −1e-4: halving
  /// would take over 6900 periods). It dies when it fell below half the start, or the rate is
  /// resolved below −1e-4. Neither, or the rate still changing toward −1e-4 (rate_change_per_period
  /// beyond rate_change_error, toward the threshold): `undecided` (never counted as surviving);
  /// except a growth resolved above zero (rate_per_period − rate_error > 0, rate_change_error
  /// finite), which survives however its rate falls: a growing amplitude tends to a cycle (its
  /// rate to 0) or grows on; it does not turn to decay.
  bool survives = false;
  double start_amplitude = 0.0;  ///< m: the watched wheelset's amplitude in the start state
  double end_amplitude = 0.0;    ///< m: its last half cycle's amplitude
  int periods = 0;               ///< periods held (fewer when it died, or grew past the bound)
  int steps = 0;                 ///< accepted Runge–Kutta steps
  // Last, so that brace-initialised holds (the report tests') keep their meaning.
  /// −1e-4 per period lies within rate_error of the rate, or the rate is still changing toward it
  /// (not a growth resolved above zero: see `survives`)
  bool undecided = false;
  double rate_per_period = 0.0;  ///< 1/period: d ln(amplitude)/d(periods), fitted over the second half
  /// 1/period: the most the peaks' errors can move the fitted rate: a wobble no larger than the
  /// largest residual, plus the peaks' sampling (a peak picked from steps of at most h is low by
  /// up to δ = −ln cos(ωh/2) in ln A). Deterministic errors, not noise: no standard error. Not a
  /// bound on a drift the fitted line absorbs (a settling still under way), which leaves no
  /// residual: rate_change_per_period shows that. Infinite when too few half cycles.
  double rate_error = 0.0;
  /// 1/period: the rate fitted over the second half of the fitted span less that over its first
  /// half; beyond rate_change_error the rate is still changing (a settling not over).
  double rate_change_per_period = 0.0;
  /// 1/period: the sum of the two halves' bounds (as rate_error); infinite when too few half cycles.
  double rate_change_error = 0.0;
};

/// The critical speed by holding the speed: the lowest speed at which a limit cycle started on the
/// branch survives options.hold_periods periods, bracketed by bisection.
struct HeldCriticalSpeed {
  std::optional<double> lowest_surviving;  ///< m/s: the lowest held speed whose cycle survived
  std::optional<double> highest_dying;     ///< m/s: the highest held speed below it whose cycle died
  /// lowest_surviving held again for 2·hold_periods still survives (the hold is long enough).
  bool doubled_hold_survives = false;
  std::vector<SpeedHold> holds;  ///< in the order held, the doubled hold last
  /// Holds still undecided when held four times as long (counted as not surviving): the answer is
  /// then not converged.
  int undecided_holds = 0;
  int steps = 0;                 ///< Σ steps of the holds
};

/// Whether the critical speed is converged.
enum class NonlinearConvergence {
  converged,      ///< held critical speed bracketed to within options.tolerance, and the doubled hold survives
  /// The rates disagree on the verdict, the confirmation failed to bracket or confirm, or the
  /// stated ramp ended while its cycle was collapsing (collapsing_at_end_speed).
  not_converged,
  not_applicable  ///< both rates agree there is no critical speed (none at the start, survives, unbounded)
};
const char* to_string(NonlinearConvergence convergence);

struct NonlinearHuntingResult {
  NonlinearHuntingVerdict verdict = NonlinearHuntingVerdict::no_limit_cycle_at_start;  ///< of the stated rate
  /// m/s: the nonlinear critical speed: the held one (hold.lowest_surviving) when the
  /// confirmation ran and bracketed it, else the ramp's at the stated rate.
  std::optional<double> critical_speed;
  double amplitude = 0.0;  ///< m: the limit cycle's amplitude at the branch end of the stated rate
  /// The bifurcation plot data: limit-cycle amplitude against speed, one point a half cycle.
  std::vector<LimitCyclePoint> curve;
  RampDown stated_rate;  ///< the ramp at options.ramp_rate
  RampDown halved_rate;  ///< the ramp at options.ramp_rate / 2
  /// |critical speed at the stated rate − at the halved rate|, m/s: how far the ramp lags;
  /// infinite when either has none (then see `convergence`).
  double convergence_difference = 0.0;
  /// 2·V(rate/2) − V(rate), m/s: the ramps' answers extrapolated to a zero rate, if the lag is
  /// linear in the rate (information: near a fold it is not, and it stays biased upward). None
  /// when either ramp is too fast (its answer more than options.hold_margin above a held speed
  /// whose cycle survives): such a ramp lost the cycle before settling on it, not by a lag.
  std::optional<double> richardson_critical_speed;
  HeldCriticalSpeed hold;  ///< the confirmation by holding the speed (empty when not run)
  /// The stated ramp is too fast for its answer: it lost the limit cycle more than
  /// options.hold_margin above a held speed whose cycle survives (the confirmation assumes the
  /// answer within that margin). The held answer stands only if the holds still bracketed it.
  bool ramp_too_fast = false;
  /// The stated ramp's verdict is survives_to_end_speed, but its amplitude was still collapsing
  /// there (its last whole half cycle fell by more than the 0.5 % a half cycle of a cycle on its
  /// branch): whether a cycle survives at the end speed is not known. Then not_converged.
  bool collapsing_at_end_speed = false;
  NonlinearConvergence convergence = NonlinearConvergence::not_applicable;
  bool converged = false;  ///< convergence == converged
  AnalysisSummary summary;
};

/// Ramps the speed down from options.start_speed, every wheelset displaced by
/// options.disturbance, integrating M q̈ + C q̇ + K q + (series dampers) = contact forces(q, q̇, V)
/// (Dormand–Prince 5(4), adaptive), twice: at the stated ramp rate and at half of it; then, when
/// the stated rate lost a limit cycle, confirms the speed by holding it (HeldCriticalSpeed).
///
/// `system` is an assembly of the lateral motions (DofSet::lateral) of a vehicle with wheelsets.
/// Throws std::invalid_argument for bad options or a vehicle without wheelsets (as
/// contact_matrices); NumericalError when the integration fails (naming the speed). A limit
/// cycle that survives to the end speed, none at the start, or unbounded growth is a verdict, never an
/// exception.
NonlinearHuntingResult solve_nonlinear_hunting(const LinearSystem& system, const NonlinearHuntingOptions& options = {});

}  // namespace railmodal
