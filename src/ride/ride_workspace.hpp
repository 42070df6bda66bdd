// The frequency-domain ride's large arrays, kept by whoever solves repeatedly (a benchmark, a
// study's worker with a ride metric, and solve_ride itself across its speeds): the receptances
// (about 9 MB on the Manchester coach's 10⁴-point grid) and each speed's spectra. Allocated and
// freed at every solve, glibc may return them to the system when they end up at the heap's top
// and fault them in again at the next solve (page clearing took 10–11 % of the ride
// benchmark's CPU, depending only on where the heap's top happened to lie); kept here, their
// pages stay the caller's (docs/ride.md, "Performance", the ninth round).
#pragma once

#include <vector>

#include "railmodal/ride.hpp"
#include "ride/ride_speed.hpp"
#include "ride/ride_transfer.hpp"

namespace railmodal::ride {

/// One worker's arrays for its speeds (solve_ride's threads take one each).
struct SpeedWorkspace {
  Receptances own;         ///< a speed's own receptances (leaf friction, the creep contact)
  Receptances passes;      ///< the friction linearisation's, rewritten at each pass
  SpeedSpectra spectra;    ///< the speed's spectra
  SpeedSpectra pass_spectra;  ///< the friction passes' stretch-rate spectra
  SpeedScratch scratch;       ///< speed_spectra's working arrays, for both (one call at a time)
};

/// The arrays of a ride solve. Holds nothing a solve reads before writing it: the answers are
/// those of solve_ride without it, bit for bit, whatever was solved in it before.
struct Workspace {
  Receptances shared;  ///< every speed's, when the system does not depend on speed
  std::vector<SpeedWorkspace> workers;
};

/// solve_ride (railmodal/ride.hpp) with its large arrays in `workspace`, which the caller keeps
/// for its next solve; null: in a workspace of the solve's own, freed on return (the public
/// solve_ride). Not for two threads at once on one workspace.
RideResult solve_ride(const LinearSystem& system, const TrackIrregularitySpectra& track,
                      const std::vector<RideOutput>& outputs, const RideOptions& options, Workspace* workspace);

}  // namespace railmodal::ride
