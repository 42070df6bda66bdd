// The hunting-stability analysis on given contact terms: what solve_hunting_stability does once
// it has the contact matrices, so that it can be tested on matrices built by hand.
#pragma once

#include <functional>
#include <optional>

#include "railmodal/hunting.hpp"
#include "railmodal/wheel_rail.hpp"

namespace railmodal::stability {

/// The contact terms at the vehicle's own conicity (nullopt) or at a given one.
using ContactSource = std::function<ContactMatrices(std::optional<double> conicity)>;

/// solve_hunting_stability with the contact terms from `contact` (called on the calling
/// thread only, once per conicity). Options must be valid.
HuntingResult hunting_analysis(const LinearSystem& system, const ContactSource& contact, const HuntingOptions& options);

}  // namespace railmodal::stability
