// The ride's enum names and the rule of its options (one place for both, so the CLI, the
// scene reader and the analysis agree on every word and bound).
#include <cmath>
#include <string>

#include "railmodal/ride.hpp"
#include "require_valid.hpp"
#include "shortest_text.hpp"

namespace railmodal {

const char* to_string(RideAxis axis) {
  switch (axis) {
    case RideAxis::longitudinal: return "longitudinal";
    case RideAxis::lateral: return "lateral";
    case RideAxis::vertical: return "vertical";
  }
  return "?";
}

std::optional<RideAxis> ride_axis_from_string(const std::string& word) {
  for (RideAxis a : {RideAxis::longitudinal, RideAxis::lateral, RideAxis::vertical})
    if (word == to_string(a)) return a;
  return std::nullopt;
}

const char* to_string(RideOutput::Kind kind) {
  switch (kind) {
    case RideOutput::Kind::point: return "point";
    case RideOutput::Kind::element_deflection: return "element_deflection";
    case RideOutput::Kind::element_force: return "element_force";
    case RideOutput::Kind::wheel_rail_force: return "wheel_rail_force";
  }
  return "?";
}

std::optional<RideOutput::Kind> ride_output_kind_from_string(const std::string& word) {
  for (RideOutput::Kind k : {RideOutput::Kind::point, RideOutput::Kind::element_deflection,
                             RideOutput::Kind::element_force, RideOutput::Kind::wheel_rail_force})
    if (word == to_string(k)) return k;
  // The hyphenated words of files written before 2026-11-27 (docs/input.md, "Names and units in
  // outputs": the vocabulary is in underscores now).
  if (word == "element-deflection") return RideOutput::Kind::element_deflection;
  if (word == "element-force") return RideOutput::Kind::element_force;
  if (word == "wheel-rail-force") return RideOutput::Kind::wheel_rail_force;
  return std::nullopt;
}

const char* to_string(RideOutput::Frame frame) { return frame == RideOutput::Frame::body ? "body" : "track"; }

std::optional<RideOutput::Frame> ride_frame_from_string(const std::string& word) {
  for (RideOutput::Frame f : {RideOutput::Frame::body, RideOutput::Frame::track})
    if (word == to_string(f)) return f;
  return std::nullopt;
}

bool reads_gravity(const RideOutput& output) {
  return output.kind == RideOutput::Kind::point && output.quantity == ResponseQuantity::acceleration &&
         output.axis != RideAxis::vertical && output.frame == RideOutput::Frame::body;
}

bool RideOptions::is_valid(std::string* why) const {
  if (speeds.empty()) return invalid(why, "speeds: at least one speed is needed");
  for (double v : speeds)
    if (!(v > 0.0) || !std::isfinite(v))
      return invalid(why, "speeds: each speed must be positive and finite (got " + shortest_text(v) + " m/s)");
  if (!(min_frequency > 0.0) || !std::isfinite(min_frequency))
    return invalid(why, "min_frequency must be positive and finite");
  if (!(max_frequency > min_frequency) || !std::isfinite(max_frequency))
    return invalid(why, "max_frequency must be finite and above min_frequency");
  if (points_per_decade < 10) return invalid(why, "points_per_decade must be at least 10");
  if (points_per_bandwidth < 1) return invalid(why, "points_per_bandwidth must be at least 1");
  if (modes < 0) return invalid(why, "modes must not be negative (0: direct solve)");
  if (!(contact_half_spacing >= 0.0) || !std::isfinite(contact_half_spacing))
    return invalid(why, "contact_half_spacing must be finite and not negative (0: from the wheelsets)");
  if (!(rolling_radius >= 0.0) || !std::isfinite(rolling_radius))
    return invalid(why, "rolling_radius must be finite and not negative (0: from the wheelsets)");
  if (!(percentile_window > 0.0) || !std::isfinite(percentile_window))
    return invalid(why, "percentile_window must be positive and finite");
  if (!(friction_tolerance > 0.0) || !(friction_tolerance < 1.0))
    return invalid(why, "friction_tolerance must lie in (0, 1)");
  if (friction_iterations < 1) return invalid(why, "friction_iterations must be at least 1");
  if (threads < 1) return invalid(why, "threads must be at least 1");
  return true;
}

}  // namespace railmodal
