// Hunting stability against speed: the options, the verdict's names, and the public entry,
// which takes the contact terms from contact_matrices() (stability/hunting_analysis.cpp does
// the work).
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "railmodal/hunting.hpp"
#include "railmodal/wheel_rail.hpp"
#include "require_valid.hpp"
#include "stability/hunting_analysis.hpp"

namespace railmodal {

namespace {
constexpr double kLowestSpeed = 1e-3;  // m/s: see HuntingOptions::is_valid
}  // namespace

const char* to_string(HuntingVerdict verdict) {
  switch (verdict) {
    case HuntingVerdict::critical_speed_in_range: return "critical_speed_in_range";
    case HuntingVerdict::stable_throughout: return "stable_throughout";
    case HuntingVerdict::unstable_at_lowest_speed: return "unstable_at_lowest_speed";
  }
  return "?";
}

std::optional<HuntingVerdict> hunting_verdict_from_string(const std::string& word) {
  for (HuntingVerdict v : {HuntingVerdict::critical_speed_in_range, HuntingVerdict::stable_throughout,
                           HuntingVerdict::unstable_at_lowest_speed})
    if (word == to_string(v)) return v;
  return std::nullopt;
}

bool HuntingOptions::is_valid(std::string* why) const {
  // The kinematic roots shrink as V while the creep terms grow as 1/V: below about 1 mm/s the
  // dense eigen-solve's round-off (ε·‖A‖, ‖A‖ ∝ 1/V) reaches the kinematic roots themselves
  // (for the bundled coach near 1.4e-6 m/s; at 1e-3 m/s the margin is some 5e5), and a root
  // would read unstable from round-off alone.
  if (!(min_speed >= kLowestSpeed && std::isfinite(min_speed)))
    return invalid(why, "min_speed must be at least 1e-3 m/s (below it the eigen-solve cannot resolve the "
                        "kinematic roots, which shrink as V, against the creep terms, which grow as 1/V)");
  if (!(max_speed > min_speed && std::isfinite(max_speed)))
    return invalid(why, "max_speed must be finite and greater than min_speed");
  if (speed_count < 2 || speed_count > 1000000) return invalid(why, "speed_count must satisfy 2 ≤ speed_count ≤ 10⁶");
  for (double c : conicities)
    if (!(c >= 0.0 && c < 1.0)) {
      char value[32];
      std::snprintf(value, sizeof value, "%g", c);
      return invalid(why, std::string("every conicity must satisfy 0 ≤ conicity < 1 (got ") + value + ")");
    }
  if (damping_threshold && !(*damping_threshold > -1.0 && *damping_threshold < 1.0))
    return invalid(why, "damping_threshold must satisfy −1 < damping_threshold < 1");
  if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 0.1))
    return invalid(why, "relative_tolerance must satisfy 1e-14 ≤ relative_tolerance ≤ 0.1");
  if (!(continuity_threshold > 0.0 && continuity_threshold <= 1.0))
    return invalid(why, "continuity_threshold must satisfy 0 < continuity_threshold ≤ 1");
  if (threads < 0) return invalid(why, "threads must be 0 (every core) or positive");
  return true;
}

HuntingResult solve_hunting_stability(const LinearSystem& system, const HuntingOptions& options) {
  require_valid(options, "HuntingOptions: ");
  if (system.vehicle.wheelsets.empty())
    throw std::invalid_argument("hunting stability: the vehicle '" + system.vehicle.name +
                                "' has no wheelsets (docs/stability.md, \"Wheelsets in a vehicle file\")");
  return stability::hunting_analysis(
      system, [&system](std::optional<double> conicity) { return contact_matrices(system, conicity); }, options);
}

}  // namespace railmodal
