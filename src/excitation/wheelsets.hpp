// The wheelsets of an assembled vehicle: its track inputs grouped by axle position.
#pragma once

#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal::excitation {

struct Wheelset {
  double x = 0.0;           ///< m, along the track (forward positive)
  std::vector<int> inputs;  ///< indices into LinearSystem::track_inputs
};

/// Wheelsets from the front (largest x) to the back; track inputs within 1 mm in x share one.
std::vector<Wheelset> wheelsets(const LinearSystem& system);

/// The same wheelsets, from this thread's list: a source asks for them with every load it
/// builds (every harmonic at every resonance of every variant of a study, and the sweep's
/// separable load), and the list depends only on the track inputs' x. It is made again only
/// when those differ, bit for bit, from the x it was made from (a study's variants share their
/// wheelbase unless it is a parameter). The reference is valid until this thread's next call.
const std::vector<Wheelset>& kept_wheelsets(const LinearSystem& system);

/// Which rail a track input stands on: +1 left (y > 0), −1 right (y < 0), 0 on the centre line.
int rail_side(const TrackInput& input);

}  // namespace railmodal::excitation
