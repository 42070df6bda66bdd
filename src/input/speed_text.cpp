// Speeds as the files write them, for command lines and [ride] tables: one reading of units
// for files and options.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "input/speed_text.hpp"
#include "input/units.hpp"
#include "railmodal/input.hpp"

namespace railmodal {
namespace {

// Enough for any ride study (a speed every 0.1 km/h from 0 to 1000 km/h), and each speed
// holds its output spectra.
constexpr double kMaxSpeeds = 10000;
// "MIN:MAX" alone: ten intervals.
constexpr int kDefaultIntervals = 10;

std::string trimmed(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

// A bare number is refused in a list or range of speeds: "100" would be 100 m/s (360 km/h), and
// a unit written on one speed of a list does not carry to the others.
bool bare_number(const std::string& text) {
  if (text.empty()) return false;
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

double positive_speed(const std::string& text) {
  // A bare zero or negative number is refused for its value first: no unit would make it a speed.
  if (bare_number(trimmed(text)) && !(std::strtod(trimmed(text).c_str(), nullptr) > 0.0))
    throw std::invalid_argument("a speed must be above zero, got '" + trimmed(text) + "'");
  if (bare_number(trimmed(text)))
    throw std::invalid_argument("give every speed its unit, such as \"" + trimmed(text) + " km/h\" or \"" +
                                trimmed(text) + " m/s\": got the bare number '" + trimmed(text) + "'");
  const double v = parse_speed(trimmed(text));
  if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument("a speed must be above zero, got '" + trimmed(text) + "'");
  return v;
}

std::vector<double> speed_range(const std::string& text, size_t colon) {
  const size_t second = text.find(':', colon + 1);
  if (second != std::string::npos && text.find(':', second + 1) != std::string::npos)
    throw std::invalid_argument("a speed range is MIN:MAX or MIN:MAX:STEP, such as \"100 km/h:200 km/h:20 km/h\"; got '" +
                                text + "'");
  const double low = positive_speed(text.substr(0, colon));
  const double high = positive_speed(text.substr(colon + 1, second == std::string::npos ? std::string::npos : second - colon - 1));
  if (!(high > low)) throw std::invalid_argument("a speed range's MAX must be above its MIN, got '" + text + "'");
  double intervals = kDefaultIntervals;
  if (second != std::string::npos) {
    const double step = positive_speed(text.substr(second + 1));
    // As many intervals as make the spacing at most STEP (round-off never adds one).
    intervals = std::ceil((high - low) / step * (1.0 - 1e-12));
    if (intervals + 1.0 > kMaxSpeeds)
      throw std::invalid_argument("the step of '" + text + "' gives more than 10000 speeds; take a coarser step");
  }
  std::vector<double> speeds;
  for (int i = 0; i <= static_cast<int>(intervals); ++i) speeds.push_back(low + (high - low) * i / intervals);
  speeds.back() = high;
  return speeds;
}

}  // namespace

bool input::has_repeated_speed(std::vector<double> speeds) {
  std::sort(speeds.begin(), speeds.end());
  return std::adjacent_find(speeds.begin(), speeds.end(), [](double a, double b) { return b - a <= 1e-14 * b; }) !=
         speeds.end();
}

double parse_speed(const std::string& text) { return input::parse_quantity(text, input::Quantity::speed); }

std::vector<double> parse_speeds(const std::string& text) {
  if (trimmed(text).empty()) throw std::invalid_argument("no speed given");
  if (const size_t colon = text.find(':'); colon != std::string::npos) {
    if (text.find(',') != std::string::npos)
      throw std::invalid_argument("give a list of speeds (with commas) or a range (with colons), not both: '" + text + "'");
    return speed_range(text, colon);
  }
  std::vector<double> speeds;
  size_t start = 0;
  for (size_t comma = text.find(','); ; comma = text.find(',', start)) {
    speeds.push_back(positive_speed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (speeds.size() > kMaxSpeeds) throw std::invalid_argument("more than 10000 speeds");
  if (input::has_repeated_speed(speeds))
    throw std::invalid_argument("a speed is given twice in '" + trimmed(text) + "': give each once");
  return speeds;
}

}  // namespace railmodal
