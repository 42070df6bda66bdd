#include "excitation/wheelsets.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace railmodal::excitation {

namespace {

// The wheelsets into `out`, reusing the storage it holds.
void wheelsets_into(const LinearSystem& system, std::vector<Wheelset>* out) {
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

// Whether the track inputs' x are `xs`, bit for bit (-0 and +0 apart, as std::memcmp sees them).
bool same_x(const LinearSystem& system, const std::vector<double>& xs) {
  if (xs.size() != system.track_inputs.size()) return false;
  for (size_t i = 0; i < xs.size(); ++i) {
    const double x = system.track_inputs[i].point.x();
    if (std::memcmp(&x, &xs[i], sizeof x) != 0) return false;
  }
  return true;
}

}  // namespace

std::vector<Wheelset> wheelsets(const LinearSystem& system) {
  std::vector<Wheelset> sets;
  sets.reserve(system.track_inputs.size());  // at most one set per input
  wheelsets_into(system, &sets);
  return sets;
}

const std::vector<Wheelset>& kept_wheelsets(const LinearSystem& system) {
  struct Kept {
    bool whole = true;       // false while the sets are rebuilt: a throw there leaves them unread
    std::vector<double> xs;  // the track inputs' x the sets were made from
    std::vector<Wheelset> sets;
  };
  thread_local Kept kept;
  if (kept.whole && same_x(system, kept.xs)) return kept.sets;
  kept.whole = false;
  kept.xs.clear();
  for (const TrackInput& t : system.track_inputs) kept.xs.push_back(t.point.x());
  wheelsets_into(system, &kept.sets);
  kept.whole = true;
  return kept.sets;
}

int rail_side(const TrackInput& input) {
  const double y = input.point.y();
  return y > 0.0 ? 1 : y < 0.0 ? -1 : 0;
}

}  // namespace railmodal::excitation
