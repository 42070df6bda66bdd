// The floor points a ride report looks at when none are named (ride.hpp, default_ride_outputs).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "ride/default_ride_outputs.hpp"

#include "railmodal/ride.hpp"
#include "shortest_text.hpp"

namespace railmodal {

namespace {

int heaviest_body(const Vehicle& v) {
  int best = 0;
  for (size_t b = 1; b < v.bodies.size(); ++b)
    if (v.bodies[b].mass > v.bodies[best].mass) best = static_cast<int>(b);
  return best;
}

// Where the car body rests: the reference x of each body under it (bogies), else the x of its
// own elements standing on the track or on wheelsets (a two-axle wagon's axles), front first,
// within 1 mm merged.
std::vector<double> support_positions(const Vehicle& v, const Body& body) {
  std::vector<double> xs;
  for (const Element& e : v.elements) {
    if (e.upper != body.name) continue;
    const auto lower = std::find_if(v.bodies.begin(), v.bodies.end(), [&](const Body& b) { return b.name == e.lower; });
    const bool wheelset = std::any_of(v.wheelsets.begin(), v.wheelsets.end(), [&](const Wheelset& w) { return w.body == e.lower; });
    xs.push_back(lower == v.bodies.end() || wheelset ? e.point.x() : lower->reference_point.x());
  }
  std::sort(xs.begin(), xs.end(), std::greater<double>());
  xs.erase(std::unique(xs.begin(), xs.end(), [](double a, double b) { return std::abs(a - b) < 1e-3; }), xs.end());
  return xs;
}

bool body_moves_laterally(const LinearSystem& system, int body) {
  for (const Dof& d : system.dofs)
    if (d.body == body && (d.motion == Motion::lateral || d.motion == Motion::roll || d.motion == Motion::yaw))
      return true;
  return false;
}

// "floor over front bogie", "floor over rear axle", "floor over support at x = 3 m".
std::string support_name(const std::vector<double>& supports, std::size_t i, bool axles) {
  const char* where = i == 0 ? "front" : i + 1 == supports.size() ? "rear" : "middle";
  if (supports.size() <= 3) return std::string("floor over ") + where + (axles ? " axle" : " bogie");
  std::ostringstream out;
  out << "floor over " << (axles ? "axle" : "support") << " at x = " << supports[i] << " m";
  return out.str();
}

}  // namespace

std::vector<RideOutput> default_ride_outputs(const LinearSystem& system) {
  const Vehicle& v = system.vehicle;
  if (v.bodies.empty()) return {};
  const int b = heaviest_body(v);
  const Body& body = v.bodies[b];
  // The floor where the vehicle gives it; otherwise the reference point's height, which the
  // ride's notes then state (default_floor_note).
  const double z = body.floor_height.value_or(body.reference_point.z());
  const std::vector<double> supports = support_positions(v, body);
  double front = body.reference_point.x(), rear = front;
  for (const Element& e : v.elements)
    if (e.upper == body.name || e.lower == body.name) {
      front = std::max(front, e.point.x());
      rear = std::min(rear, e.point.x());
    }
  const bool two_axle = std::none_of(v.elements.begin(), v.elements.end(), [&](const Element& e) {
    return e.upper == body.name && !e.lower.empty() &&
           std::none_of(v.wheelsets.begin(), v.wheelsets.end(), [&](const Wheelset& w) { return w.body == e.lower; });
  });
  // The body's ends: a bending beam gives them (its length is the body's); otherwise the
  // vehicle does not say where the body ends, and the points are named after what they are
  // measured from, the outermost element on the body, rather than passing for the ends.
  bool ends_known = false;
  if (body.bending) {
    const double centre = body.bending->centre.value_or(body.centre_of_gravity.x());
    front = centre + 0.5 * body.bending->length;
    rear = centre - 0.5 * body.bending->length;
    ends_known = true;
  }
  std::vector<std::pair<std::string, double>> points;
  for (size_t i = 0; i < supports.size(); ++i) points.push_back({support_name(supports, i, two_axle), supports[i]});
  points.push_back({"floor at mid-car", 0.5 * (front + rear)});
  if (front - rear > 2.0) {
    points.push_back({ends_known ? "floor 1 m from front end" : "floor 1 m inboard of front support", front - 1.0});
    points.push_back({ends_known ? "floor 1 m from rear end" : "floor 1 m inboard of rear support", rear + 1.0});
  }
  const bool lateral = body_moves_laterally(system, b);
  std::vector<RideOutput> out;
  for (const auto& [name, x] : points)
    for (RideAxis axis : {RideAxis::vertical, RideAxis::lateral}) {
      if (axis == RideAxis::lateral && !lateral) continue;
      RideOutput o;
      o.name = name + ", " + to_string(axis);
      o.kind = RideOutput::Kind::point;
      o.body = body.name;
      o.point = Eigen::Vector3d(x, 0.0, z);
      o.axis = axis;
      o.quantity = ResponseQuantity::acceleration;
      out.push_back(o);
    }
  return out;
}

namespace ride {

std::optional<std::string> default_floor_note(const LinearSystem& system, const std::vector<RideOutput>& outputs) {
  const Vehicle& v = system.vehicle;
  if (v.bodies.empty() || outputs.empty()) return std::nullopt;
  const Body& body = v.bodies[heaviest_body(v)];
  if (body.floor_height) return std::nullopt;
  const std::vector<RideOutput> defaults = default_ride_outputs(system);
  const bool uses_default = std::any_of(outputs.begin(), outputs.end(), [&](const RideOutput& o) {
    return std::any_of(defaults.begin(), defaults.end(), [&](const RideOutput& d) {
      return o.kind == d.kind && o.name == d.name && o.body == d.body && o.point == d.point && o.axis == d.axis;
    });
  });
  if (!uses_default) return std::nullopt;
  return "floor height not given: the default floor points lie at z = " + shortest_text(body.reference_point.z(), 6) +
         " m, the reference point of '" + body.name +
         "' (for the templates the plane of its springs, below a real floor), where a lateral acceleration lacks the "
         "roll's share at the floor's height; give `floor_height` (m above the plane of the axles) in the body's "
         "table, or name the points in [[ride.output]]";
}

}  // namespace ride

}  // namespace railmodal
