// The hunting-stability report.
// PLACEHOLDER until issue 20's report lands.
#include <stdexcept>

#include "railmodal/hunting_report.hpp"

namespace railmodal {

void write_hunting_stability(std::ostream&, const HuntingResult&, OutputFormat) {
  throw std::logic_error("write_hunting_stability: not built yet");
}

}  // namespace railmodal
