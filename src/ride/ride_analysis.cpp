// Placeholder of the frequency-domain ride (helper "ride-core" replaces this file).
#include <stdexcept>

#include "railmodal/ride.hpp"

namespace railmodal {

const char* to_string(RideAxis) { throw std::logic_error("ride: not built yet"); }
std::optional<RideAxis> ride_axis_from_string(const std::string&) { throw std::logic_error("ride: not built yet"); }
const char* to_string(RideOutput::Kind) { throw std::logic_error("ride: not built yet"); }
std::optional<RideOutput::Kind> ride_output_kind_from_string(const std::string&) {
  throw std::logic_error("ride: not built yet");
}
std::vector<RideOutput> default_ride_outputs(const LinearSystem&) { throw std::logic_error("ride: not built yet"); }
bool RideOptions::is_valid(std::string*) const { throw std::logic_error("ride: not built yet"); }
RideResult solve_ride(const LinearSystem&, const TrackIrregularitySpectra&, const std::vector<RideOutput>&,
                      const RideOptions&) {
  throw std::logic_error("ride: not built yet");
}

}  // namespace railmodal
