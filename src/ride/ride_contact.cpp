// The creep contact of the lateral ride (ride_contact.hpp; docs/ride.md, "Lateral ride through
// the creep forces", derives the alignment's generalised force).
#include "ride/ride_contact.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>

#include "model/wheelset_dofs.hpp"

namespace railmodal::ride {

bool acts_through_contact(const LinearSystem& system) {
  for (const Wheelset& w : system.vehicle.wheelsets)
    for (const Dof& d : system.dofs)
      if (d.motion == Motion::lateral && d.body >= 0 && d.body < static_cast<int>(system.vehicle.bodies.size()) &&
          system.vehicle.bodies[d.body].name == w.body)
        return true;
  return false;
}

CreepContact creep_contact(const LinearSystem& system) {
  CreepContact c;
  c.matrices = contact_matrices(system);
  for (std::size_t i = 0; i < system.vehicle.wheelsets.size(); ++i) {
    const model::WheelsetDofs dofs = model::wheelset_dofs(system, system.vehicle.wheelsets[i]);
    const ResolvedContact& r = c.matrices.wheelsets[i];
    const double kappa = 1.0 + r.roll_parameter * r.rolling_radius / r.contact_half_spacing;
    c.lateral.push_back(dofs.lateral);
    c.x.push_back(system.vehicle.bodies[dofs.body].centre_of_gravity.x());
    c.relative_share.push_back((kappa - 1.0) / kappa);
  }
  return c;
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
    t.element = -1;
    t.point = Eigen::Vector3d(contact.x[i], 0.0, 0.0);
    t.load_per_displacement = Eigen::MatrixXd::Zero(n, 3);
    t.load_per_velocity = Eigen::MatrixXd::Zero(n, 3);
    t.load_per_displacement.col(1) = m.stiffness.col(j);
    t.load_per_velocity.col(1) = contact.relative_share[i] * m.creep_damping.col(j) / speed + speed * m.gyroscopic.col(j);
    s.track_inputs.push_back(t);
  }
  return s;
}

Eigen::VectorXcd first_order_roots(const LinearSystem& system) {
  const int n = system.size();
  const int d = static_cast<int>(system.series_dampers.size());
  // x = (q, q̇, F): M q̈ = −K q − C q̇ − Σ stretchᵀF, Ḟ = k(stretch·q̇ − F/c).
  const Eigen::LLT<Eigen::MatrixXd> mass(system.mass);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n + d, 2 * n + d);
  a.block(0, n, n, n).setIdentity();
  a.block(n, 0, n, n) = -mass.solve(system.stiffness);
  a.block(n, n, n, n) = -mass.solve(system.damping);
  for (int k = 0; k < d; ++k) {
    const SeriesDamperRow& s = system.series_dampers[k];
    a.block(n, 2 * n + k, n, 1) = -mass.solve(s.stretch.transpose());
    a.block(2 * n + k, n, 1, n) = s.stiffness * s.stretch;
    a(2 * n + k, 2 * n + k) = -s.stiffness / s.damping;
  }
  return Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues();
}

bool decays(const Eigen::VectorXcd& roots) {
  // Round-off: the eigenvalues of a matrix of norm ‖A‖ are found within ~1e-16·‖A‖; an undamped
  // mode's roots (real part zero) land there, a growing one far above. 1e-9 of the largest root
  // leaves seven orders of margin above round-off; within it a root counts as not growing (the
  // undamped case is answered by the modes, solve_ride's unbounded outputs).
  const double largest = roots.cwiseAbs().maxCoeff();
  return roots.real().maxCoeff() <= 1e-9 * largest;
}

}  // namespace railmodal::ride
