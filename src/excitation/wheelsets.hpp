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

/// The same wheelsets into `sets`, reusing the storage it holds: a source asks for them with
/// every load it builds (every harmonic at every resonance of every variant of a study), and a
/// list kept by the caller makes them without an allocation once it has grown.
void wheelsets(const LinearSystem& system, std::vector<Wheelset>* sets);

/// Which rail a track input stands on: +1 left (y > 0), −1 right (y < 0), 0 on the centre line.
int rail_side(const TrackInput& input);

}  // namespace railmodal::excitation
