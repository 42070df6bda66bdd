// Every number of a Vehicle, and the rest of it as text (vehicle_numbers.hpp). One walk over
// the structs serves both: it hands each double to `number` and writes the rest to `shape`.
#include "input/vehicle_numbers.hpp"

#include <optional>

namespace railmodal::input {
namespace {

struct Walk {
  std::vector<double*>* numbers = nullptr;  // null: the shape only
  std::string* shape = nullptr;             // null: the numbers only

  void number(double& x) {
    if (numbers) numbers->push_back(&x);
  }
  void vector(Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) number(v(i));
  }
  // The shape's text is made only when it is asked for: a study's fast path walks every
  // variant's vehicle for its numbers alone, and would otherwise build (and drop) a string
  // per name, flag and count.
  void text(const std::string& t) {
    if (shape) *shape += t + '\x1f';  // a separator no name holds
  }
  void text(const char* t) {
    if (shape) text(std::string(t));
  }
  void flag(bool present) { text(present ? "1" : "0"); }
  void count(size_t n) {
    if (shape) text(std::to_string(n));
  }
  template <class T, class F>
  void optional(std::optional<T>& o, F f) {
    flag(o.has_value());
    if (o) f(*o);
  }
  void optional_number(std::optional<double>& o) {
    optional(o, [this](double& x) { number(x); });
  }

  void body(Body& b) {
    text(b.name);
    number(b.mass);
    vector(b.inertia);
    vector(b.centre_of_gravity);
    vector(b.reference_point);
    count(b.held.size());
    for (Motion m : b.held) text(to_string(m));
    flag(b.longitudinal_free);
    optional(b.bending, [this](BodyBending& g) {
      number(g.length);
      optional_number(g.centre);
      optional(g.beam, [this](BodyBending::Beam& beam) {
        number(beam.bending_stiffness);
        number(beam.mass_per_length);
      });
      optional(g.mode, [this](BodyBending::Mode& mode) {
        number(mode.frequency);
        number(mode.modal_mass);
      });
      number(g.damping_ratio);
    });
    optional_number(b.floor_height);
  }
  void stages(std::vector<SpringStage>& list) {
    count(list.size());
    for (SpringStage& s : list) {
      text(s.kind);
      number(s.stiffness);
      count(static_cast<size_t>(s.count));
      number(s.relative_friction);
      optional(s.curve, [this](LoadDeflectionCurve& c) {
        count(c.deflection.size());
        for (double& d : c.deflection) number(d);
        count(c.load.size());
        for (double& p : c.load) number(p);
      });
    }
  }
  void element(Element& e) {
    text(e.name);
    text(e.lower);
    text(e.upper);
    vector(e.point);
    stages(e.vertical_stages);
    stages(e.lateral_stages);
    stages(e.longitudinal_stages);
    optional(e.hanger, [this](SwingHanger& h) {
      number(h.length);
      number(h.inclination);
    });
    vector(e.rotational_stiffness);
    number(e.vertical_damping);
    number(e.lateral_damping);
    number(e.longitudinal_damping);
    count(e.series_dampers.size());
    for (SeriesDamper& d : e.series_dampers) {
      text(to_string(d.direction));
      number(d.damping);
      number(d.stiffness);
    }
  }
  void wheelset(Wheelset& w) {
    text(w.body);
    number(w.spin_inertia);
    WheelRailContact& c = w.contact;
    number(c.rolling_radius);
    number(c.contact_half_spacing);
    number(c.conicity);
    optional_number(c.contact_angle_parameter);
    optional_number(c.roll_parameter);
    optional_number(c.axle_load);
    optional(c.creep, [this](CreepCoefficients& k) {
      number(k.f11);
      number(k.f22);
      number(k.f23);
      number(k.f33);
    });
    optional(c.hertz, [this](HertzContactInput& h) {
      optional_number(h.wheel_load);
      optional_number(h.wheel_transverse_radius);
      number(h.rail_head_radius);
      number(h.youngs_modulus);
      number(h.poisson_ratio);
    });
  }
  void vehicle(Vehicle& v) {
    text(v.name);
    text(v.source);
    number(v.gravity);
    count(v.bodies.size());
    for (Body& b : v.bodies) body(b);
    count(v.elements.size());
    for (Element& e : v.elements) element(e);
    count(v.wheelsets.size());
    for (Wheelset& w : v.wheelsets) wheelset(w);
  }
};

}  // namespace

std::vector<double*> vehicle_numbers(Vehicle* vehicle) {
  std::vector<double*> numbers;
  vehicle_numbers(vehicle, &numbers);
  return numbers;
}

void vehicle_numbers(Vehicle* vehicle, std::vector<double*>* numbers) {
  numbers->clear();
  Walk{numbers, nullptr}.vehicle(*vehicle);
}

std::string vehicle_shape(const Vehicle& vehicle) {
  std::string shape;
  Vehicle copy = vehicle;  // the walk hands out writable numbers; the shape reads none of them
  Walk{nullptr, &shape}.vehicle(copy);
  return shape;
}

}  // namespace railmodal::input
