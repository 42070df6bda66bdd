// Study files for the study tests: the book's two-axle wagon (Example 3 reduced) and a
// one-source scene written beside each study.
#pragma once

#include <string>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {

/// The loaded two-axle freight wagon of the two-axle digest's Example 3; `spring_extra` is
/// added to its leaf spring's table (", relative_friction = 0.075" for its friction).
inline std::string example3_wagon(const std::string& spring_extra = "") {
  return R"(
[vehicle]
name = "wagon"
template = "two-axle"
gravity = "981 cm/s^2"
[body]
weight = "22626 kgf"
cg_height = "100 cm"
radius_of_gyration = { roll = "110 cm", pitch = "260 cm", yaw = "260 cm" }
[suspension]
wheelbase = "3810 mm"
spring_spacing = "211.4 cm"
spring = [{ kind = "leaf", static_deflection = "57.2 mm")" +
         spring_extra + " }]\n";
}

/// 10 m rail joints of 5 mm, 20–150 km/h by 1 km/h, vertical motions.
inline const char* kJointsScene = R"(
[scene]
name = "joints"
dofs = "vertical"
[speed]
min = "20 km/h"
max = "150 km/h"
step = "1 km/h"
[[source]]
kind = "rail_joints"
rail_length = "10 m"
dip_depth = "5 mm"
)";

/// Writes wagon.toml (`wagon`), scene.toml and study.toml ([study] head, `head`, `body`) in
/// the test's folder and returns the study's path.
inline std::string write_study(const std::string& wagon, const std::string& body, const std::string& head = "") {
  write_temp("wagon.toml", wagon);
  write_temp("scene.toml", kJointsScene);
  return write_temp("study.toml",
                    "[study]\nname = \"s\"\nvehicle = \"wagon.toml\"\nscene = \"scene.toml\"\n" + head + body);
}

/// The error the study at `path` gives, with its location (a test failure if none).
inline InputError study_error_at(const std::string& path, const std::string& what) {
  try {
    load_study(path);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << what;
  return InputError("", 0, 0, "");
}

}  // namespace railmodal::test
