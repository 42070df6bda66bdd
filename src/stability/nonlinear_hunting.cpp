// The nonlinear critical speed: two ramp-downs, at the stated rate and at half of it, and the
// convergence check between them (docs/stability.md, "The nonlinear critical speed").
#include "railmodal/nonlinear_hunting.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "stability/lateral_equations.hpp"
#include "stability/ramp_down.hpp"

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
  }
  return "?";
}

std::optional<NonlinearHuntingVerdict> nonlinear_hunting_verdict_from_string(const std::string& word) {
  for (NonlinearHuntingVerdict v :
       {NonlinearHuntingVerdict::limit_cycle_dies_out, NonlinearHuntingVerdict::survives_to_end_speed,
        NonlinearHuntingVerdict::no_limit_cycle_at_start})
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
  if (!(tolerance > 0.0 && finite(tolerance))) return fail("tolerance must be positive");
  return true;
}

NonlinearHuntingResult solve_nonlinear_hunting(const LinearSystem& system, const NonlinearHuntingOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument("solve_nonlinear_hunting: " + why);
  using clock = std::chrono::steady_clock;
  NonlinearHuntingResult r;
  r.summary.analysis = "nonlinear critical speed";
  r.summary.method = "ramp-down of the speed, Dormand-Prince 5(4) with adaptive steps, twice (rate and half rate)";
  auto start = clock::now();
  const auto stage = [&](const std::string& name) {
    const auto now = clock::now();
    r.summary.stages.push_back({name, std::chrono::duration<double>(now - start).count()});
    start = now;
  };
  const stability::LateralEquations equations(system, options);
  stage("equations");
  r.stated_rate = stability::ramp_down(equations, options, options.ramp_rate);
  stage("ramp at the stated rate");
  r.halved_rate = stability::ramp_down(equations, options, options.ramp_rate / 2.0);
  stage("ramp at half the rate");

  r.verdict = r.stated_rate.verdict;
  r.critical_speed = r.stated_rate.critical_speed;
  r.amplitude = r.stated_rate.amplitude;
  r.curve = r.stated_rate.curve;
  r.convergence_difference = r.stated_rate.critical_speed && r.halved_rate.critical_speed
                                 ? std::abs(*r.stated_rate.critical_speed - *r.halved_rate.critical_speed)
                                 : std::numeric_limits<double>::infinity();
  r.converged =
      r.stated_rate.verdict == r.halved_rate.verdict &&
      (r.verdict != NonlinearHuntingVerdict::limit_cycle_dies_out || r.convergence_difference <= options.tolerance);
  r.summary.checks.push_back(
      {"critical speed change on halving the ramp rate, m/s",
       r.verdict == NonlinearHuntingVerdict::limit_cycle_dies_out ? r.convergence_difference : 0.0, options.tolerance,
       r.converged});
  return r;
}

}  // namespace railmodal
