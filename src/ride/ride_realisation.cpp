// Placeholder of the time-domain ride (helper "ride-time" replaces this file).
#include <stdexcept>

#include "railmodal/ride_simulation.hpp"

namespace railmodal {

double TrackGeometry::length() const { throw std::logic_error("ride simulation: not built yet"); }
bool TrackSynthesisOptions::is_valid(std::string*) const { throw std::logic_error("ride simulation: not built yet"); }
TrackGeometry synthesise_track(const TrackIrregularitySpectra&, const TrackSynthesisOptions&) {
  throw std::logic_error("ride simulation: not built yet");
}
TrackGeometry load_track_geometry(const std::string&) { throw std::logic_error("ride simulation: not built yet"); }
bool RideSimulationOptions::is_valid(std::string*) const { throw std::logic_error("ride simulation: not built yet"); }
RideSimulationResult simulate_ride(const LinearSystem&, const TrackGeometry&, const std::vector<RideOutput>&,
                                   const RideSimulationOptions&) {
  throw std::logic_error("ride simulation: not built yet");
}
RideFftChecks check_ride_realisation(const LinearSystem&, const TrackIrregularitySpectra&, const TrackGeometry&,
                                     const RideSimulationResult&, const RideSimulationOptions&) {
  throw std::logic_error("ride simulation: not built yet");
}

}  // namespace railmodal
