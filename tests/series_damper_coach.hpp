// The coach with yaw dampers that the series-damper tests share (damped modes, ride).
#pragma once

#include <fstream>
#include <iterator>
#include <string>

#include "test_support.hpp"

namespace railmodal::test {

/// The Manchester benchmark coach (data/vehicles/manchester_benchmark_coach.toml) with secondary
/// yaw dampers, series dampers of the study data/studies/coach_hunting_yaw_dampers.toml's values
/// (400 kN·s/m with 10 MN/m in series, 2.6 m apart): the vehicle a VAMPIRE or SIMPACK user models.
inline Vehicle coach_with_yaw_dampers() {
  std::ifstream in(data_file("manchester_benchmark_coach.toml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find("\n[secondary]");
  if (at == std::string::npos) ADD_FAILURE() << "no [secondary] in the coach";
  const size_t line_end = text.find('\n', at + 1);
  text.insert(line_end + 1,
              "yaw_damper = { damping = \"400 kN*s/m\", series_stiffness = \"10 MN/m\", spacing = \"2.6 m\" }\n");
  return load_vehicle(write_temp("coach_yaw_dampers.toml", text));
}

}  // namespace railmodal::test
