// Hunting stability against speed.
// PLACEHOLDER until issue 20's stability solver lands.
#include <stdexcept>

#include "railmodal/hunting.hpp"

namespace railmodal {

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

bool HuntingOptions::is_valid(std::string*) const { return true; }

HuntingResult solve_hunting_stability(const LinearSystem&, const HuntingOptions&) {
  throw std::logic_error("solve_hunting_stability: not built yet");
}

}  // namespace railmodal
