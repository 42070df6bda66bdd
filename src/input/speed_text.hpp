// Speeds as the files and options write them (parse_speed, parse_speeds: railmodal/input.hpp),
// and the one rule a list of them keeps wherever it is written.
#pragma once

#include <vector>

namespace railmodal::input {

/// Whether `speeds` (m/s) hold one speed twice, "the same" to the 15 significant digits the
/// reports print in km/h ("100 km/h" and "27.7777777777778 m/s" differ in the 16th), so that no
/// two rows read alike. The same speed twice would be solved and reported twice: a slip, which
/// the readers refuse rather than guess at.
bool has_repeated_speed(std::vector<double> speeds);

}  // namespace railmodal::input
