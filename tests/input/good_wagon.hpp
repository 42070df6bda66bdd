// The smallest valid vehicle file the reader tests start from: a two-axle wagon in the book's
// units. Each test replaces or adds a line (vehicle_reader_test.cpp, floor_height_reader_test.cpp).
#pragma once

#include <string>

namespace railmodal::test {

inline const std::string kGoodWagon = R"([vehicle]
name = "test wagon"
template = "two-axle"
[body]
weight = "20000 kgf"
cg_height = "100 cm"
radius_of_gyration = { roll = "110 cm", pitch = "260 cm" }
[suspension]
wheelbase = "400 cm"
spring_spacing = "200 cm"
spring = { kind = "coil", stiffness = "1000 kgf/cm" }
)";

}  // namespace railmodal::test
