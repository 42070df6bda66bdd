// Placeholder of the ride report (helper "ride-cli" replaces this file).
#include "railmodal/ride_report.hpp"

#include <stdexcept>

namespace railmodal {

void write_ride(std::ostream&, const RideResult&, OutputFormat, const RideSimulationResult*, const RideFftChecks*) {
  throw std::logic_error("ride report: not built yet");
}
void write_ride(std::ostream&, const RideResult&, OutputFormat, const std::string&, const Provenance&,
                const RideSimulationResult*, const RideFftChecks*) {
  throw std::logic_error("ride report: not built yet");
}

}  // namespace railmodal
