// The modes tables keep their columns apart however large the numbers (issue 18 item 15: at
// ω ≥ 1e8 the frequency, period and ω of a stiff mode ran together into one word).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// The whitespace-separated words of the table line that starts with `start`.
std::vector<std::string> words_of_line(const std::string& text, const std::string& start) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(start, 0) == 0) {
      std::istringstream in(line);
      std::vector<std::string> words;
      for (std::string w; in >> w;) words.push_back(w);
      return words;
    }
  return {};
}

// Issue 17 review, item 8: the DOF column was 18 wide, so a freed surge's label
// (bogie1.longitudinal, 19) pushed its row's shape columns one place right of the heading's.
// Every line of the shape table now has one length: the heading and each row line up.
TEST(ModesTable, LongDofLabelsKeepTheShapeColumnsAligned) {
  Vehicle v = load_vehicle(data_file("manchester_benchmark_coach.toml"));
  for (Body& b : v.bodies) b.longitudinal_free = true;
  const LinearSystem sys = assemble(v, DofSet::vertical);
  std::ostringstream out;
  write_modes(out, sys, solve_modes(sys), OutputFormat::table);
  std::istringstream lines(out.str());
  std::string line;
  while (std::getline(lines, line) && line.rfind("mode shapes", 0) != 0) {
  }
  ASSERT_TRUE(std::getline(lines, line));  // the heading: "dof", then the mode numbers
  const size_t width = line.size();
  int rows = 0;
  bool longitudinal = false;
  for (; std::getline(lines, line) && !line.empty(); ++rows) {
    EXPECT_EQ(line.size(), width) << line;
    longitudinal = longitudinal || line.rfind("bogie1.longitudinal ", 0) == 0;
  }
  EXPECT_EQ(rows, sys.size());
  EXPECT_TRUE(longitudinal);
}

// One DOF, m = 1 kg, k = 1e18 N/m: ω = 1e9 rad/s, f = 1.59e8 Hz.
LinearSystem stiff_oscillator() {
  LinearSystem s;
  s.dofs = {{"a_degree_of_freedom_label_longer_than_its_column", 0, Motion::bounce}};
  s.mass = Eigen::MatrixXd::Constant(1, 1, 1.0);
  s.stiffness = Eigen::MatrixXd::Constant(1, 1, 1e18);
  s.damping = Eigen::MatrixXd::Zero(1, 1);
  s.gravity_stiffness = Eigen::MatrixXd::Zero(1, 1);
  return s;
}

TEST(ModesTable, StiffModeColumnsStaySeparate) {
  const LinearSystem system = stiff_oscillator();
  std::ostringstream out;
  write_modes(out, "stiff", solve_modes(system), OutputFormat::table);
  // #, name, f, T, ω: five words (the name has no space).
  const auto row = words_of_line(out.str(), "1   ");
  ASSERT_EQ(row.size(), 5u) << out.str();
  EXPECT_EQ(row[2], "159154943.0919") << out.str();
  // From 1e9 on, scientific with the column's decimals (report::fixed): fixed notation of a
  // stiff link's ω ran to as many digits as the exponent, none meaningful past the 16th.
  EXPECT_EQ(row[4], "1.000e+09") << out.str();
  // The shapes table: the long label and the entry are two words.
  EXPECT_EQ(words_of_line(out.str(), "a_degree").size(), 2u) << out.str();
}

TEST(ModesTable, StiffDampedModeColumnsStaySeparate) {
  std::ostringstream out;
  write_damped_modes(out, stiff_oscillator(), solve_damped_modes(stiff_oscillator()), OutputFormat::table);
  // #, name, f_d, ζ, f_n, f_0, stability.
  const auto row = words_of_line(out.str(), "1   ");
  ASSERT_EQ(row.size(), 7u) << out.str();
  EXPECT_EQ(row[2], "159154943.0919") << out.str();
}

// An absurd stiffness (1e300 N/m on 1 kg, possible only from the library: the readers refuse
// magnitudes past 1e30) keeps every column a number of a few digits.
TEST(ModesTable, AbsurdFrequencyStaysANumberOfAFewDigits) {
  LinearSystem system = stiff_oscillator();
  system.stiffness(0, 0) = 1e300;
  std::ostringstream out;
  write_modes(out, "absurd", solve_modes(system), OutputFormat::table);
  const auto row = words_of_line(out.str(), "1   ");
  ASSERT_EQ(row.size(), 5u) << out.str();
  EXPECT_EQ(row[2], "1.5915e+149") << out.str();
  EXPECT_EQ(row[4], "1.000e+150") << out.str();
}

// A centre of oscillation is given with its datum (audit 2026-11-27b: "roll, z = -2.060 m" read as
// a height above the body or the rail, where it is the vehicle frame's z from the axle plane).
// The figure is the mode's CentreOfOscillation, printed to the millimetre.
TEST(ModesTable, CentresOfOscillationSayTheirDatum) {
  const LinearSystem sys = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::all);
  const ModalResult modes = solve_modes(sys);
  std::ostringstream table, csv;
  write_modes(table, sys, modes, OutputFormat::table);
  write_modes(csv, sys, modes, OutputFormat::csv);
  int rolls = 0;
  for (const Mode& m : modes.modes) {
    if (!m.centre || m.centre->at_infinity) continue;
    char figure[32];
    // As the writer rounds: a centre within half a millimetre of 0 is 0.000, never -0.000.
    std::snprintf(figure, sizeof figure, "%.3f", std::abs(m.centre->position) < 5e-4 ? 0.0 : m.centre->position);
    const std::string said = m.centre->about == "roll" ? std::string("roll, z = ") + figure + " m from the axle plane"
                                                       : std::string("pitch, x = ") + figure + " m in the vehicle frame";
    EXPECT_NE(table.str().find(said), std::string::npos) << said;
    EXPECT_NE(csv.str().find(said), std::string::npos) << said;
    rolls += m.centre->about == "roll";
  }
  EXPECT_GT(rolls, 0);  // the coach's sways: the datum was said at least once
}

}  // namespace
}  // namespace railmodal::test
