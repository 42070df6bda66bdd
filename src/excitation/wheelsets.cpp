#include "excitation/wheelsets.hpp"

#include <algorithm>
#include <cmath>

namespace railmodal::excitation {

std::vector<Wheelset> wheelsets(const LinearSystem& system) {
  constexpr double kSameAxle = 1e-3;  // m: springs of one axle share its x to well within this
  std::vector<Wheelset> sets;
  sets.reserve(system.track_inputs.size());  // at most one set per input (a source asks per load)
  for (int i = 0; i < static_cast<int>(system.track_inputs.size()); ++i) {
    const double x = system.track_inputs[i].point.x();
    auto it = std::find_if(sets.begin(), sets.end(),
                           [&](const Wheelset& w) { return std::abs(w.x - x) <= kSameAxle; });
    if (it == sets.end()) {
      sets.push_back({x, {}});
      sets.back().inputs.reserve(2);  // a wheel on each rail: one allocation per set, not two
      sets.back().inputs.push_back(i);
    } else {
      it->inputs.push_back(i);
    }
  }
  std::sort(sets.begin(), sets.end(), [](const Wheelset& a, const Wheelset& b) { return a.x > b.x; });
  return sets;
}

int rail_side(const TrackInput& input) {
  const double y = input.point.y();
  return y > 0.0 ? 1 : y < 0.0 ? -1 : 0;
}

}  // namespace railmodal::excitation
