// The creep contact of the lateral ride (ride_contact.hpp; docs/ride.md, "Lateral ride through
// the creep forces", derives the alignment's generalised force).
#include "ride/ride_contact.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <stdexcept>

#include "model/element_stiffness.hpp"
#include "model/point_motion.hpp"
#include "model/wheelset_dofs.hpp"
#include "stability/first_order_system.hpp"

namespace railmodal::ride {

bool acts_through_contact(const LinearSystem& system) {
  for (const Wheelset& w : system.vehicle.wheelsets)
    for (const Dof& d : system.dofs)
      if (d.motion == Motion::lateral && d.body >= 0 && d.body < static_cast<int>(system.vehicle.bodies.size()) &&
          system.vehicle.bodies[d.body].name == w.body)
        return true;
  return false;
}

namespace {

// The generalised forces, per radian of a wheelset's roll with the rails, of the elements
// attached to it: a point at height h above the axle plane (where its centre of gravity is,
// wheelset_dofs) moves sideways by −θ·h with the roll, so an element's lateral stretch (upper
// end minus lower end) changes by d·θ, and its force −k·aᵀ(a·q + d·θ) (a its stretch per DOF)
// has the input part −k·aᵀ·d·θ (−c·aᵀ·d·θ̇ from its damper).
void add_suspension_roll(const LinearSystem& system, const std::string& wheelset, CreepContact* c) {
  const Vehicle& v = system.vehicle;
  const int n = system.size();
  Eigen::VectorXd stiff = Eigen::VectorXd::Zero(n), viscous = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    if (e.upper != wheelset && e.lower != wheelset) continue;
    // The rails' roll also twists an element's roll stiffness and stretches a lateral series
    // damper; neither is in the terms below, so such an element is refused, not left out.
    const bool lateral_series = std::any_of(e.series_dampers.begin(), e.series_dampers.end(),
                                            [](const SeriesDamper& s) { return s.direction == Motion::lateral; });
    if (e.rotational_stiffness.x() != 0.0 || lateral_series)
      throw IrregularityComponentError(TrackIrregularity::cross_level,
                                       "ride: cross-level through the contact: element '" + e.name + "' on wheelset '" +
                                           wheelset + "' has " +
                                           (lateral_series ? "a lateral series damper" : "a roll stiffness") +
                                           ", which the rails' roll would load and the ride does not model; leave the "
                                           "cross-level out, or move the element off the wheelset");
    if (k >= system.element_loads.size())
      throw std::invalid_argument("ride: cross-level through the contact: element '" + e.name +
                                  "' has no static load in the assembled system (assemble the vehicle first)");
    const double h = e.point.z();
    const double d = (e.upper == wheelset ? -h : 0.0) - (e.lower == wheelset ? -h : 0.0);
    if (d == 0.0) continue;
    const int upper = model::body_index(system, e.upper), lower = model::body_index(system, e.lower);
    Eigen::RowVectorXd a = Eigen::RowVectorXd::Zero(n);
    if (upper >= 0) a += model::point_displacement_map(system, upper, e.point).row(1);
    if (lower >= 0) a -= model::point_displacement_map(system, lower, e.point).row(1);
    stiff -= model::lateral_stiffness(e, system.element_loads[k]) * d * a.transpose();
    viscous -= e.lateral_damping * d * a.transpose();
  }
  c->suspension_roll_stiff.push_back(stiff);
  c->suspension_roll_viscous.push_back(viscous);
}

}  // namespace

CreepContact creep_contact(const LinearSystem& system, double contact_half_spacing, bool cross_level) {
  CreepContact c;
  c.matrices = contact_matrices(system);
  c.cross_level = cross_level;
  for (std::size_t i = 0; i < system.vehicle.wheelsets.size(); ++i) {
    const Wheelset& w = system.vehicle.wheelsets[i];
    const model::WheelsetDofs dofs = model::wheelset_dofs(system, w);
    const ResolvedContact& r = c.matrices.wheelsets[i];
    const double kappa = 1.0 + r.roll_parameter * r.rolling_radius / r.contact_half_spacing;
    c.lateral.push_back(dofs.lateral);
    c.x.push_back(system.vehicle.bodies[dofs.body].centre_of_gravity.x());
    c.relative_share.push_back((kappa - 1.0) / kappa);
    if (!cross_level) continue;
    c.yaw.push_back(dofs.yaw);
    c.lever.push_back(dofs.lever);
    c.rolling_radius.push_back(r.rolling_radius);
    c.axle_load.push_back(r.axle_load);
    c.spin_term.push_back(w.spin_inertia / r.rolling_radius);
    // θ = Δz/(2b), b as cross_level_directions takes it (the option, else this wheelset's l0),
    // so the contact and the elements' vertical inputs see one roll.
    const double b = contact_half_spacing > 0.0 ? contact_half_spacing : r.contact_half_spacing;
    c.roll_per_cross_level.push_back(1.0 / (2.0 * b));
    add_suspension_roll(system, w.body, &c);
  }
  return c;
}

RollLoad rail_roll_load(const CreepContact& contact, std::size_t i, double speed, bool contact_only) {
  // Per radian of the rails' roll θ (docs/ride.md, "Cross-level through the contact"): the
  // rails roll about the rail top, r0 below the axle, so the wheelset's place on them is
  // y − y_θ with y_θ = −r0·θ; against it act every term of K_c's lateral column and, since the
  // contact point's lateral velocity ẏ + r0·φ̇ with the absolute roll φ = θ + σ(y − y_θ)/l0 is
  // κ(ẏ − ẏ_θ), the whole ẏ column of C_c/V and V·G. Besides: the normal loads W, square to the
  // rolled rail plane, lean by θ (−W·θ sideways at the axle, T-transposed onto the DOFs), and the
  // spin momentum I_y·V/r0 tilted by the absolute roll rate θ̇ asks the yaw moment −I_y(V/r0)θ̇.
  const ContactMatrices& m = contact.matrices;
  const int j = contact.lateral[i], yaw = contact.yaw[i];
  const double r0 = contact.rolling_radius[i], scale = contact.roll_per_cross_level[i];
  RollLoad load;
  load.stiff = -r0 * m.stiffness.col(j);
  load.viscous = -r0 * (m.creep_damping.col(j) / speed + speed * m.gyroscopic.col(j));
  load.stiff(j) -= contact.axle_load[i];
  load.stiff(yaw) -= contact.axle_load[i] * contact.lever[i];
  load.viscous(yaw) -= contact.spin_term[i] * speed;
  if (!contact_only) {
    load.stiff += contact.suspension_roll_stiff[i];
    load.viscous += contact.suspension_roll_viscous[i];
  }
  load.stiff *= scale;
  load.viscous *= scale;
  return load;
}

Eigen::Vector3d contact_direction(int element, TrackIrregularity kind) {
  if (element == kAlignmentInput && kind == TrackIrregularity::alignment) return Eigen::Vector3d::UnitY();
  if (element == kRailRollInput && kind == TrackIrregularity::cross_level) return Eigen::Vector3d::UnitX();
  return Eigen::Vector3d::Zero();
}

LinearSystem with_creep(const LinearSystem& system, const CreepContact& contact, double speed) {
  LinearSystem s = system;
  const ContactMatrices& m = contact.matrices;
  s.damping += m.creep_damping / speed + speed * m.gyroscopic;
  s.stiffness += m.stiffness;
  const int n = system.size();
  for (std::size_t i = 0; i < contact.lateral.size(); ++i) {
    // Every term of K_c's lateral column acts on y − y_t (the rolling-radius difference, the
    // contact angles, the spin); of the ẏ column, the roll's share ρ of the lateral creepage and
    // the gyroscopic yaw moment act on ẏ − ẏ_t, the rest (ẏ/V − ψ) on the absolute motion.
    const int j = contact.lateral[i];
    TrackInput t;
    t.element = kAlignmentInput;
    t.point = Eigen::Vector3d(contact.x[i], 0.0, 0.0);
    t.load_per_displacement = Eigen::MatrixXd::Zero(n, 3);
    t.load_per_velocity = Eigen::MatrixXd::Zero(n, 3);
    t.load_per_displacement.col(1) = m.stiffness.col(j);
    t.load_per_velocity.col(1) = contact.relative_share[i] * m.creep_damping.col(j) / speed + speed * m.gyroscopic.col(j);
    s.track_inputs.push_back(t);
  }
  if (!contact.cross_level) return s;
  for (std::size_t i = 0; i < contact.lateral.size(); ++i) {
    const RollLoad load = rail_roll_load(contact, i, speed, false);
    TrackInput t;
    t.element = kRailRollInput;
    t.point = Eigen::Vector3d(contact.x[i], 0.0, 0.0);
    t.load_per_displacement = Eigen::MatrixXd::Zero(n, 3);
    t.load_per_velocity = Eigen::MatrixXd::Zero(n, 3);
    t.load_per_displacement.col(0) = load.stiff;
    t.load_per_velocity.col(0) = load.viscous;
    s.track_inputs.push_back(t);
  }
  return s;
}

namespace {

// The first-order form's matrix A, x = (q, q̇, F): M q̈ = −K q − C q̇ − Σ stretchᵀF,
// Ḟ = k(stretch·q̇ − F/c): the hunting analysis' (stability::FirstOrderSystem) with its contact
// terms zero, since with_creep has put them into C and K already; with them zero the speed
// enters nowhere (0/V and V·0), so any speed will do. Its eigenvalues are this file's former
// copy's to the bit (the Manchester coach on wheelsets at 5–80 m/s, with and without yaw dampers).
Eigen::MatrixXd first_order_matrix(const LinearSystem& system) {
  const int n = system.size();
  ContactMatrices none;
  none.creep_damping = none.gyroscopic = none.stiffness = Eigen::MatrixXd::Zero(n, n);
  return stability::FirstOrderSystem(system, none).state_matrix(1.0);
}

// Round-off: the eigenvalues of a matrix of norm ‖A‖ are found within ~1e-16·‖A‖; an undamped
// mode's roots (real part zero) land there, a growing one far above. 1e-9 of the largest root
// leaves seven orders of margin above round-off; within it a root counts as not growing (the
// undamped case is answered by the modes, solve_ride's unbounded outputs).
bool grows(std::complex<double> root, double largest) { return root.real() > 1e-9 * largest; }

// Whether the free motion with these roots decays: none grows. Above the linear critical speed
// it does not, and the stationary response of what the growing motion moves is unbounded.
bool decays(const Eigen::VectorXcd& roots) {
  const double largest = roots.cwiseAbs().maxCoeff();
  return std::none_of(roots.begin(), roots.end(), [&](std::complex<double> r) { return grows(r, largest); });
}

}  // namespace

Eigen::VectorXcd first_order_roots(const LinearSystem& system) {
  return Eigen::EigenSolver<Eigen::MatrixXd>(first_order_matrix(system), false).eigenvalues();
}

std::vector<GrowingMotion> growing_motions(const LinearSystem& system) {
  const Eigen::MatrixXd a = first_order_matrix(system);
  const Eigen::VectorXcd roots = Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues();
  if (decays(roots)) return {};  // the usual case: no eigenvectors needed
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, true);
  const Eigen::VectorXcd& values = solver.eigenvalues();
  const Eigen::MatrixXcd vectors = solver.eigenvectors();
  const double largest = values.cwiseAbs().maxCoeff();
  std::vector<GrowingMotion> out;
  for (Eigen::Index k = 0; k < values.size(); ++k)
    if (grows(values(k), largest) && values(k).imag() >= 0.0)  // a pair once, by its Im λ ≥ 0 root
      out.push_back({values(k), vectors.col(k).head(system.size())});
  return out;
}

}  // namespace railmodal::ride
