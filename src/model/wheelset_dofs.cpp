// Where a wheelset sits in a vehicle and in an assembled system (wheelset_dofs.hpp).
#include "model/wheelset_dofs.hpp"

#include <stdexcept>

namespace railmodal::model {
namespace {

[[noreturn]] void fail(const Wheelset& w, const std::string& what) {
  throw std::invalid_argument("contact_matrices: wheelset '" + w.body + "': " + what);
}

}  // namespace

const Wheelset* wheelset_of(const Vehicle& vehicle, const std::string& body) {
  for (const Wheelset& w : vehicle.wheelsets)
    if (w.body == body) return &w;
  return nullptr;
}

int wheelset_carrier(const Vehicle& vehicle, const std::string& body) {
  for (const Element& e : vehicle.elements) {
    const std::string& other = e.lower == body ? e.upper : e.upper == body ? e.lower : std::string();
    if (other.empty() || wheelset_of(vehicle, other) != nullptr) continue;
    for (std::size_t b = 0; b < vehicle.bodies.size(); ++b)
      if (vehicle.bodies[b].name == other) return static_cast<int>(b);
    return -1;  // the first such element joins it to the track
  }
  return -1;
}

WheelsetDofs wheelset_dofs(const LinearSystem& system, const Wheelset& w) {
  const Vehicle& v = system.vehicle;
  WheelsetDofs d;
  for (std::size_t i = 0; i < v.bodies.size() && d.body < 0; ++i)
    if (v.bodies[i].name == w.body) d.body = static_cast<int>(i);
  if (d.body < 0) fail(w, "no body of that name in the vehicle");
  const Body& b = v.bodies[d.body];
  // The contact acts at the axle centre, taken as the centre of gravity, on the track's centre
  // line in the axle plane (y = z = 0): elsewhere the contact points and the elements' levers
  // would disagree silently (and a lateral offset from the reference point adds m·Δy² of yaw
  // inertia through the longitudinal motion). Only x may vary: the lever below.
  const Eigen::Vector3d& cg = b.centre_of_gravity;
  const Eigen::Vector3d& ref = b.reference_point;
  if (cg.y() != 0.0 || cg.z() != 0.0 || ref.y() != 0.0 || ref.z() != 0.0)
    fail(w,
         "its centre of gravity (the axle centre) and reference point must lie on the track's centre line in "
         "the axle plane (y = z = 0; only x may vary)");
  for (int i = 0; i < system.size(); ++i) {
    if (system.dofs[i].body != d.body) continue;
    switch (system.dofs[i].motion) {
      case Motion::lateral:
        d.lateral = i;
        break;
      case Motion::yaw:
        d.yaw = i;
        break;
      case Motion::longitudinal:
        break;  // rolling along: the contact terms leave it alone
      default:
        // Bounce, roll and pitch follow the rails in the linear model (the roll through σ).
        fail(w, std::string("its ") + to_string(system.dofs[i].motion) +
                    " must be held: a wheelset's bounce, roll and pitch follow the rails");
    }
  }
  if (d.lateral < 0 || d.yaw < 0)
    fail(w,
         "its lateral and yaw motions must be free degrees of freedom of the system (assemble "
         "the lateral or all motions, and do not hold them)");
  d.lever = cg.x() - ref.x();
  return d;
}

}  // namespace railmodal::model
