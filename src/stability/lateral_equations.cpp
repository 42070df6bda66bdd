// The lateral equations of a vehicle on its wheelsets with the creep forces of a linear or
// saturating law and a flange (docs/stability.md, "The equations of motion" for the linear
// terms, "The nonlinear critical speed" for the rest).
#include "stability/lateral_equations.hpp"

#include <algorithm>
#include <cmath>

#include "model/wheelset_dofs.hpp"
#include "railmodal/errors.hpp"
#include "stability/creep_saturation.hpp"

namespace railmodal::stability {
namespace {

bool has(const NonlinearHuntingOptions& o, NonlinearEffect e) {
  return std::find(o.effects.begin(), o.effects.end(), e) != o.effects.end();
}

WheelsetContact locate(const LinearSystem& system, const Wheelset& w, const ResolvedContact& r) {
  // contact_matrices has already checked the wheelset's DOFs; this finds them the same way.
  const model::WheelsetDofs dofs = model::wheelset_dofs(system, w);
  WheelsetContact c;
  c.lateral = dofs.lateral;
  c.yaw = dofs.yaw;
  c.lever = dofs.lever;
  c.geometry = {r.rolling_radius, r.contact_half_spacing, r.conicity, r.contact_angle_parameter, r.roll_parameter};
  c.creep = r.creep;
  c.axle_load = r.axle_load;
  c.gyroscopic =
      model::gyroscopic_coefficient(w.spin_inertia, r.roll_parameter, r.rolling_radius, r.contact_half_spacing);
  return c;
}

}  // namespace

LateralEquations::LateralEquations(const LinearSystem& system, const NonlinearHuntingOptions& options)
    : dofs_(system.size()),
      damping_(system.damping),
      stiffness_(system.stiffness),
      mass_(system.mass),
      dampers_(system.series_dampers),
      linear_(contact_matrices(system)),
      saturation_(has(options, NonlinearEffect::creep_saturation)),
      flange_(has(options, NonlinearEffect::flange_contact)),
      contact_angle_(options.contact_angle),
      flange_clearance_(options.flange_clearance),
      flange_stiffness_(options.flange_stiffness) {
  if (mass_.info() != Eigen::Success)
    throw NumericalError("solve_nonlinear_hunting: the mass matrix is not positive definite");
  for (std::size_t i = 0; i < system.vehicle.wheelsets.size(); ++i) {
    WheelsetContact c = locate(system, system.vehicle.wheelsets[i], linear_.wheelsets[i]);
    c.friction_limit = options.friction_coefficient * options.wheel_load.value_or(c.axle_load / 2.0);
    wheelsets_.push_back(c);
  }
}

model::WheelContactForces LateralEquations::creep_forces(const WheelsetContact& w,
                                                         const model::WheelCreepage& c) const {
  return saturation_ ? saturated_creep_forces(w.creep, c, w.friction_limit) : model::linear_creep_forces(w.creep, c);
}

Eigen::VectorXd LateralEquations::contact_forces(double speed, const Eigen::VectorXd& q,
                                                 const Eigen::VectorXd& rate) const {
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(dofs_);
  for (const WheelsetContact& w : wheelsets_) {
    const double y = q[w.lateral] + w.lever * q[w.yaw];
    const double y_rate = rate[w.lateral] + w.lever * rate[w.yaw];
    model::WheelsetCreepages c = model::wheelset_creepages(w.geometry, {y, q[w.yaw], y_rate, rate[w.yaw], speed});
    if (saturation_) {
      // The centred wheelset's spin −δ0/r0 on the left, +δ0/r0 on the right: equal and opposite
      // forces that cancel in the linear law but use part of each wheel's adhesion in this one.
      c.left.spin -= contact_angle_ / w.geometry.rolling_radius;
      c.right.spin += contact_angle_ / w.geometry.rolling_radius;
    }
    const model::WheelsetLoad load =
        model::wheelset_load(w.geometry, creep_forces(w, c.left), creep_forces(w, c.right));
    // The gravitational stiffness and the gyroscopic coupling, as in the linear model
    // (contact_matrices): −W·ε·y/l0 laterally; −V·G·(ẏ, ψ̇) with G = [[0, −g], [g, 0]].
    double lateral = load.lateral -
                     w.axle_load * w.geometry.contact_angle_parameter * y / w.geometry.contact_half_spacing +
                     speed * w.gyroscopic * rate[w.yaw];
    const double yaw = load.yaw - speed * w.gyroscopic * y_rate;
    // The flange: a spring of the rail's lateral stiffness once the play is taken up.
    if (flange_ && std::abs(y) > flange_clearance_)
      lateral -= flange_stiffness_ * (y - std::copysign(flange_clearance_, y));
    // Onto the DOFs: (y_axle, ψ) = T (q_lateral, q_yaw), generalised forces Tᵀ·(F, M).
    forces[w.lateral] += lateral;
    forces[w.yaw] += w.lever * lateral + yaw;
  }
  return forces;
}

void LateralEquations::derivative(double speed, const Eigen::VectorXd& x, Eigen::VectorXd* dx) const {
  const int n = dofs_;
  const auto q = x.head(n);
  const auto rate = x.segment(n, n);
  Eigen::VectorXd force = contact_forces(speed, q, rate) - damping_ * rate - stiffness_ * q;
  dx->resize(x.size());
  for (std::size_t k = 0; k < dampers_.size(); ++k) {
    const SeriesDamperRow& d = dampers_[k];
    const double f = x[2 * n + static_cast<int>(k)];
    force -= d.stretch.transpose() * f;
    (*dx)[2 * n + static_cast<int>(k)] = d.stiffness * (d.stretch.dot(rate) - f / d.damping);
  }
  dx->head(n) = rate;
  dx->segment(n, n) = mass_.solve(force);
}

double LateralEquations::leading_lateral(const Eigen::VectorXd& x) const {
  const WheelsetContact& w = wheelsets_.front();
  return x[w.lateral] + w.lever * x[w.yaw];
}

}  // namespace railmodal::stability
