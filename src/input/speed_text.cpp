// A speed as the files write it, for command lines: one reading of units for files and options.
#include "input/units.hpp"
#include "railmodal/input.hpp"

namespace railmodal {

double parse_speed(const std::string& text) { return input::parse_quantity(text, input::Quantity::speed); }

}  // namespace railmodal
