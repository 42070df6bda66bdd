// The linearised wheel–rail contact terms of a vehicle's wheelsets.
// PLACEHOLDER until issue 20's contact work lands.
#include <stdexcept>

#include "railmodal/wheel_rail.hpp"

namespace railmodal {

ContactMatrices contact_matrices(const LinearSystem&, std::optional<double>) {
  throw std::logic_error("contact_matrices: not built yet");
}

}  // namespace railmodal
