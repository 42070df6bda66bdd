// Helpers shared by the tests: temporary vehicle files and the bundled data directory.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "railmodal/railmodal.hpp"

namespace railmodal::test {

inline std::string data_file(const std::string& name) {
  return std::string(RAILMODAL_DATA_DIR) + "/vehicles/" + name;
}

/// Writes `text` to a fresh file in a temporary directory of the running test (ctest runs
/// tests in parallel processes: a shared directory would let them overwrite each other's
/// files) and returns its path. Files of one test share the directory, so they can name
/// each other by relative paths.
inline std::string write_temp(const std::string& name, const std::string& text) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string folder = test ? std::string(test->test_suite_name()) + "." + test->name() : "no_test";
  for (char& c : folder)
    if (c == '/') c = '_';  // parameterised names hold '/'
  const auto dir = std::filesystem::temp_directory_path() / "railmodal_tests" / folder;
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

/// The oscillatory mode with this name (fails the test when there is none).
inline const Mode& mode_named(const ModalResult& r, const std::string& name) {
  for (const auto& m : r.modes)
    if (m.name == name) return m;
  ADD_FAILURE() << "no mode named '" << name << "'";
  static Mode none;
  return none;
}

inline Body* body_named(Vehicle& v, const std::string& name) {
  for (auto& b : v.bodies)
    if (b.name == name) return &b;
  return nullptr;
}

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;           // the book's g = 981 cm/s²
constexpr double kKgf = 9.80665;      // N per kgf
constexpr double kKgfPerCm = 980.665;  // N/m per kgf/cm

}  // namespace railmodal::test
