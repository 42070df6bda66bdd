#include "excitation/wheelsets.hpp"

#include <algorithm>
#include <cmath>

namespace railmodal::excitation {

void wheelsets(const LinearSystem& system, std::vector<Wheelset>* out) {
  constexpr double kSameAxle = 1e-3;  // m: springs of one axle share its x to well within this
  std::vector<Wheelset>& sets = *out;
  size_t used = 0;  // the sets found so far: sets[0, used); those after keep their storage for reuse
  for (int i = 0; i < static_cast<int>(system.track_inputs.size()); ++i) {
    const double x = system.track_inputs[i].point.x();
    const auto found = std::find_if(sets.begin(), sets.begin() + static_cast<std::ptrdiff_t>(used),
                                    [&](const Wheelset& w) { return std::abs(w.x - x) <= kSameAxle; });
    if (found == sets.begin() + static_cast<std::ptrdiff_t>(used)) {
      if (used == sets.size()) sets.emplace_back();
      Wheelset& w = sets[used++];
      w.x = x;
      w.inputs.clear();
      w.inputs.reserve(2);  // a wheel on each rail: one allocation per set, not two
      w.inputs.push_back(i);
    } else {
      found->inputs.push_back(i);
    }
  }
  sets.resize(used);
  std::sort(sets.begin(), sets.end(), [](const Wheelset& a, const Wheelset& b) { return a.x > b.x; });
}

std::vector<Wheelset> wheelsets(const LinearSystem& system) {
  std::vector<Wheelset> sets;
  sets.reserve(system.track_inputs.size());  // at most one set per input
  wheelsets(system, &sets);
  return sets;
}

int rail_side(const TrackInput& input) {
  const double y = input.point.y();
  return y > 0.0 ? 1 : y < 0.0 ? -1 : 0;
}

}  // namespace railmodal::excitation
