// The linearised wheel–rail contact terms of a vehicle's wheelsets: creep damping C_c/V,
// gyroscopic V·G, creep and gravitational stiffness K_c (docs/stability.md, "The equations of
// motion", derives every term and cites its sources).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "model/wheelset_creepage.hpp"
#include "model/wheelset_dofs.hpp"
#include "railmodal/wheel_rail.hpp"
#include "shortest_text.hpp"

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void fail(const Wheelset& w, const std::string& what) {
  throw std::invalid_argument("contact_matrices: wheelset '" + w.body + "': " + what);
}

void require(bool ok, const Wheelset& w, const std::string& name, double value, const char* rule) {
  if (!ok) fail(w, name + " = " + shortest_text(value) + " " + rule);
}

// W: what the rails carry under the wheelset: given, or from its vertical equilibrium (its
// weight, the static loads of the elements standing on it, less those of elements hanging it
// from below). Sets r.axle_load and says where it came from.
void resolve_axle_load(const LinearSystem& system, const Wheelset& w, int body, ResolvedContact* r) {
  const Vehicle& v = system.vehicle;
  if (w.contact.axle_load) {
    r->axle_load = *w.contact.axle_load;
    r->axle_load_source = "given";
  } else {
    double load = v.bodies[body].mass * v.gravity;
    bool carries = false;
    for (std::size_t k = 0; k < v.elements.size() && k < system.element_loads.size(); ++k) {
      if (v.elements[k].lower == w.body) load += system.element_loads[k];
      if (v.elements[k].upper == w.body) load -= system.element_loads[k];
      if ((v.elements[k].lower == w.body || v.elements[k].upper == w.body) && system.element_loads[k] != 0.0)
        carries = true;
    }
    r->axle_load = load;
    r->axle_load_source = carries ? "static loads" : "own weight only";
  }
  require(r->axle_load > 0.0 && std::isfinite(r->axle_load), w, "axle load", r->axle_load, "N: must be positive");
}

CreepCoefficients resolve_creep(const Wheelset& w, double rolling_radius, double load,
                                std::optional<HertzContact>* ellipse) {
  const WheelRailContact& c = w.contact;
  if (c.creep.has_value() == c.hertz.has_value())
    fail(w, "give exactly one of the creep coefficients and the Hertz contact");
  CreepCoefficients f;
  if (c.creep) {
    f = *c.creep;
  } else {
    HertzContactInput in = *c.hertz;
    if (!in.wheel_load) in.wheel_load = load / 2.0;  // the static load of one of its two wheels
    *ellipse = hertz_contact(in, rolling_radius);
    f = creep_coefficients(**ellipse, in.youngs_modulus, in.poisson_ratio);
  }
  require(f.f11 > 0.0 && std::isfinite(f.f11), w, "f11", f.f11, "N: must be positive");
  require(f.f22 > 0.0 && std::isfinite(f.f22), w, "f22", f.f22, "N: must be positive");
  require(std::isfinite(f.f23), w, "f23", f.f23, "N·m: must be finite");
  require(f.f33 >= 0.0 && std::isfinite(f.f33), w, "f33", f.f33, "N·m²: must be ≥ 0");
  return f;
}

ResolvedContact resolve(const LinearSystem& system, const Wheelset& w, int body, std::optional<double> conicity) {
  const WheelRailContact& c = w.contact;
  ResolvedContact r;
  r.body = w.body;
  r.rolling_radius = c.rolling_radius;
  r.contact_half_spacing = c.contact_half_spacing;
  r.conicity = conicity.value_or(c.conicity);
  require(r.rolling_radius > 0.0 && std::isfinite(r.rolling_radius), w, "rolling radius r0", r.rolling_radius,
          "m: must be positive");
  require(r.contact_half_spacing > 0.0 && std::isfinite(r.contact_half_spacing), w, "contact half spacing l0",
          r.contact_half_spacing, "m: must be positive");
  require(r.conicity >= 0.0 && r.conicity < 1.0, w, "conicity", r.conicity, "must be ≥ 0 and below 1");
  // Conical wheels on knife-edge rails: the wheelset rolls by (r_left − r_right)/(2l0) = λy/l0, so
  // σ = λ; the contact angles, fixed on the cones, turn with it, so δ_left − δ_right = 2λy/l0 and
  // ε = λ (docs/stability.md).
  r.contact_angle_parameter = c.contact_angle_parameter.value_or(r.conicity);
  r.roll_parameter = c.roll_parameter.value_or(r.conicity);
  require(std::isfinite(r.contact_angle_parameter), w, "contact angle parameter", r.contact_angle_parameter,
          "must be finite");
  require(std::isfinite(r.roll_parameter), w, "roll parameter", r.roll_parameter, "must be finite");
  require(w.spin_inertia >= 0.0 && std::isfinite(w.spin_inertia), w, "spin inertia", w.spin_inertia,
          "kg·m²: must be ≥ 0");
  resolve_axle_load(system, w, body, &r);
  r.creep = resolve_creep(w, r.rolling_radius, r.axle_load, &r.ellipse);
  r.klingel_wavelength = r.conicity > 0.0
                             ? 2.0 * kPi * std::sqrt(r.rolling_radius * r.contact_half_spacing / r.conicity)
                             : std::numeric_limits<double>::infinity();
  return r;
}

// The two contact forces on the wheelset from a unit of one state variable, at V = 1 (so a rate
// enters as rate/V: the creep damping's coefficient of 1/V).
model::WheelsetLoad unit_load(const model::WheelsetGeometry& g, const CreepCoefficients& f,
                              const model::WheelsetState& s) {
  const auto c = model::wheelset_creepages(g, s);
  return model::wheelset_load(g, model::linear_creep_forces(f, c.left), model::linear_creep_forces(f, c.right));
}

}  // namespace

ContactMatrices contact_matrices(const LinearSystem& system, std::optional<double> conicity) {
  const Vehicle& v = system.vehicle;
  if (v.wheelsets.empty())
    throw std::invalid_argument("contact_matrices: the vehicle '" + v.name + "' has no wheelsets");
  if (conicity && !(*conicity >= 0.0 && *conicity < 1.0))
    throw std::invalid_argument("contact_matrices: conicity = " + shortest_text(*conicity) +
                                " must be ≥ 0 and below 1");
  const int n = system.size();
  ContactMatrices out;
  out.creep_damping = Eigen::MatrixXd::Zero(n, n);
  out.gyroscopic = Eigen::MatrixXd::Zero(n, n);
  out.stiffness = Eigen::MatrixXd::Zero(n, n);
  for (const Wheelset& w : v.wheelsets) {
    for (const Wheelset& other : v.wheelsets)
      if (&other != &w && other.body == w.body) fail(w, "listed twice among the wheelsets");
    const model::WheelsetDofs dofs = model::wheelset_dofs(system, w);
    ResolvedContact r = resolve(system, w, dofs.body, conicity);
    const model::WheelsetGeometry g{r.rolling_radius, r.contact_half_spacing, r.conicity, r.contact_angle_parameter,
                                    r.roll_parameter};

    // Over the axle centre's (y, ψ): minus the contact loads per unit of each variable.
    Eigen::Matrix2d stiffness, damping, gyroscopic;
    const model::WheelsetState unit[4] = {{1, 0, 0, 0, 1}, {0, 1, 0, 0, 1}, {0, 0, 1, 0, 1}, {0, 0, 0, 1, 1}};
    for (int j = 0; j < 2; ++j) {
      const auto k = unit_load(g, r.creep, unit[j]);
      const auto c = unit_load(g, r.creep, unit[j + 2]);
      stiffness.col(j) << -k.lateral, -k.yaw;
      damping.col(j) << -c.lateral, -c.yaw;
    }
    // Gravitational stiffness: the normal loads W/2 lean inwards at contact angles whose
    // difference is 2εy/l0, leaving a lateral resultant −W·ε·y/l0 (restoring for ε > 0).
    stiffness(0, 0) += r.axle_load * r.contact_angle_parameter / r.contact_half_spacing;
    // Gyroscopic: the spin angular momentum I_y·V/r0 about the axle, tilted by the roll
    // φ = σy/l0 and the yaw ψ; its rate asks the yaw moment I_y(V/r0)φ̇ and the roll moment
    // −I_y(V/r0)ψ̇. With the roll slaved to y, the roll moment's virtual work through
    // δφ = σδy/l0 is the lateral force of the skew-symmetric partner (energy is conserved). Seen
    // as forces, the rails take the roll moment as a normal-load difference whose inclination ±δ0
    // gives δ0 where σ stands: exact for cones (σ = δ0 = λ), an approximation for worn profiles.
    const double g_coefficient =
        model::gyroscopic_coefficient(w.spin_inertia, r.roll_parameter, r.rolling_radius, r.contact_half_spacing);
    gyroscopic << 0.0, -g_coefficient, g_coefficient, 0.0;

    // From the axle centre to the DOFs: (y_axle, ψ) = T (y_ref, ψ), generalised forces Tᵀ·F.
    Eigen::Matrix2d t;
    t << 1.0, dofs.lever, 0.0, 1.0;
    const int index[2] = {dofs.lateral, dofs.yaw};
    const Eigen::Matrix2d k = t.transpose() * stiffness * t;
    const Eigen::Matrix2d c = t.transpose() * damping * t;
    const Eigen::Matrix2d gy = t.transpose() * gyroscopic * t;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        out.stiffness(index[a], index[b]) += k(a, b);
        out.creep_damping(index[a], index[b]) += c(a, b);
        out.gyroscopic(index[a], index[b]) += gy(a, b);
      }
    out.wheelsets.push_back(std::move(r));
  }
  return out;
}

}  // namespace railmodal
