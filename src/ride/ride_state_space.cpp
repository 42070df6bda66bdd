#include "ride/ride_state_space.hpp"

#include <Eigen/Dense>
#include <stdexcept>

#include "model/point_motion.hpp"
#include "model/series_damper_strokes.hpp"
#include "railmodal/errors.hpp"
#include "ride/ride_transfer.hpp"

namespace railmodal::ride {
namespace {

// M, C and K hold no wheel–rail contact: the creep forces and the gravitational stiffness that
// steer a wheelset on the rails are added by the frequency-domain ride (ride_contact.hpp), not by
// the march. A wheelset free to move laterally or yaw would stand on its suspension alone: a
// wrong answer given silently, so it is refused.
void refuse_wheelsets_without_contact(const LinearSystem& system) {
  for (const Wheelset& w : system.vehicle.wheelsets)
    for (const Dof& d : system.dofs)
      if (d.body >= 0 && system.vehicle.bodies[static_cast<size_t>(d.body)].name == w.body &&
          (d.motion == Motion::lateral || d.motion == Motion::yaw))
        throw std::invalid_argument("ride simulation: wheelset '" + w.body + "' moves " + to_string(d.motion) +
                                    " (" + d.label + "), and the time-domain ride does not model the wheel–rail "
                                    "creep contact that guides it on the rails; run the ride in the frequency "
                                    "domain, or give the vertical degrees of freedom only");
}

}  // namespace

RideStateSpace ride_state_space(const LinearSystem& system) {
  refuse_wheelsets_without_contact(system);
  refuse_series_dampers_on_track(system, "ride simulation");
  const int n = system.size();
  if (n == 0) throw std::invalid_argument("ride simulation: the system has no degrees of freedom");
  for (int i = 0; i < n; ++i)
    if (system.mass.row(i).cwiseAbs().maxCoeff() == 0.0)
      throw std::invalid_argument("ride simulation: degree of freedom '" + system.dofs[i].label +
                                  "' is massless; the time-domain ride needs inertia on every degree of freedom");
  const Eigen::LLT<Eigen::MatrixXd> llt(system.mass);
  if (llt.info() != Eigen::Success) throw NumericalError("ride simulation: the mass matrix is not positive definite");
  RideStateSpace s;
  s.n = n;
  s.strokes = static_cast<int>(system.series_dampers.size());
  const int d = s.strokes;
  s.mass_inverse = llt.solve(Eigen::MatrixXd::Identity(n, n));
  const int m = 3 * static_cast<int>(system.track_inputs.size());
  s.Bd = Eigen::MatrixXd::Zero(n, m);
  s.Bv = Eigen::MatrixXd::Zero(n, m);
  for (size_t i = 0; i < system.track_inputs.size(); ++i) {
    s.Bd.middleCols(3 * i, 3) = system.track_inputs[i].load_per_displacement;
    s.Bv.middleCols(3 * i, 3) = system.track_inputs[i].load_per_velocity;
  }
  // The strokes' rows and columns of the extended M, C, K (the series dampers' only part in it).
  const LinearSystem extended = d > 0 ? model::with_series_damper_strokes(system) : LinearSystem();
  const Eigen::MatrixXd& K = d > 0 ? extended.stiffness : system.stiffness;  // (n + d) square
  s.position_stiffness = K.topRows(n);
  const Eigen::MatrixXd MinvBv = s.mass_inverse * s.Bv;
  s.A = Eigen::MatrixXd::Zero(s.states(), s.states());
  s.A.block(0, n, n, n).setIdentity();
  const Eigen::MatrixXd MinvK = -s.mass_inverse * s.position_stiffness;  // on (q, u)
  s.A.block(n, 0, n, n) = MinvK.leftCols(n);
  s.A.block(n, 2 * n, n, d) = MinvK.rightCols(d);
  s.A.block(n, n, n, n) = -s.mass_inverse * system.damping;
  for (int j = 0; j < d; ++j) {  // c u̇ = −(K_uq q + K_uu u) = k(stretch·q − u)
    const double c = extended.damping(n + j, n + j);
    s.A.block(2 * n + j, 0, 1, n) = -K.block(n + j, 0, 1, n) / c;
    s.A(2 * n + j, 2 * n + j) = -K(n + j, n + j) / c;
  }
  s.B = Eigen::MatrixXd::Zero(s.states(), m);
  s.B.topRows(n) = MinvBv;
  s.B.middleRows(n, n) = s.mass_inverse * (s.Bd - system.damping * MinvBv);
  return s;
}

namespace {

int body_index(const LinearSystem& system, const RideOutput& output) {
  for (size_t b = 0; b < system.vehicle.bodies.size(); ++b)
    if (system.vehicle.bodies[b].name == output.body) return static_cast<int>(b);
  throw std::invalid_argument("ride simulation: output '" + output.name + "' names no body '" + output.body + "'");
}

int element_index(const LinearSystem& system, const RideOutput& output) {
  for (size_t e = 0; e < system.vehicle.elements.size(); ++e)
    if (system.vehicle.elements[e].name == output.element) return static_cast<int>(e);
  throw std::invalid_argument("ride simulation: output '" + output.name + "' names no element '" + output.element + "'");
}

// r·q as a row on (s, w, ẇ) for r·q, r·q̇ or r·q̈ (see ride_state_space.hpp):
//   q̇ = v + M⁻¹Bv w;   q̈ = −M⁻¹K_qq q − M⁻¹K_qu u − M⁻¹C v + M⁻¹(Bd − C M⁻¹Bv) w + M⁻¹Bv ẇ.
OutputRow motion_row(const LinearSystem& system, const RideStateSpace& model, const Eigen::RowVectorXd& r,
                     ResponseQuantity quantity) {
  const int n = model.n, d = model.strokes;
  OutputRow row{Eigen::RowVectorXd::Zero(model.states()), Eigen::RowVectorXd::Zero(model.B.cols()),
                Eigen::RowVectorXd::Zero(model.B.cols()), Eigen::RowVectorXd()};
  const Eigen::RowVectorXd rMinv = r * model.mass_inverse;
  switch (quantity) {
    case ResponseQuantity::displacement:
      row.Ls.head(n) = r;
      break;
    case ResponseQuantity::velocity:
      row.Ls.segment(n, n) = r;
      row.Lw = rMinv * model.Bv;
      break;
    case ResponseQuantity::acceleration: {
      const Eigen::RowVectorXd elastic = -rMinv * model.position_stiffness;  // on (q, u)
      row.Ls.head(n) = elastic.head(n);
      row.Ls.tail(d) = elastic.tail(d);
      row.Ls.segment(n, n) = -rMinv * system.damping;
      row.Lw = rMinv * (model.Bd - system.damping * model.mass_inverse * model.Bv);
      row.Ld = rMinv * model.Bv;
      row.La = r;
      break;
    }
  }
  return row;
}

}  // namespace

std::vector<OutputRow> output_rows(const LinearSystem& system, const RideStateSpace& model,
                                   const std::vector<RideOutput>& outputs) {
  std::vector<OutputRow> rows;
  for (const RideOutput& output : outputs) {
    if (output.kind == RideOutput::Kind::point) {
      const Eigen::MatrixXd map = model::point_displacement_map(system, body_index(system, output), output.point);
      OutputRow row = motion_row(system, model, map.row(static_cast<int>(output.axis)), output.quantity);
      // An accelerometer on the body reads g·φ (−g·θ) besides r·q̈: a row on q (ride_transfer.hpp).
      const Eigen::RowVectorXd gravity = gravity_row(system, output);
      if (gravity.size()) row.Ls.head(model.n) += gravity;
      rows.push_back(row);
    } else if (output.kind == RideOutput::Kind::element_deflection && output.axis == RideAxis::vertical) {
      const int e = element_index(system, output);
      OutputRow row = motion_row(system, model, system.element_vertical_map.row(e), ResponseQuantity::displacement);
      for (size_t i = 0; i < system.track_inputs.size(); ++i)
        if (system.track_inputs[i].element == e) row.Lw(3 * static_cast<int>(i) + 2) -= 1.0;  // the track's own
      rows.push_back(row);
    } else if (output.kind == RideOutput::Kind::wheel_rail_force && output.axis != RideAxis::vertical) {
      // The frequency domain has it from the creep contact (docs/ride.md, "The wheel–rail force
      // across the track"); the march's system is the vehicle's M, C, K without the contact.
      throw std::invalid_argument("ride simulation: output '" + output.name + "': the " + to_string(output.axis) +
                                  " wheel–rail force is the creep contact's, which the time-domain march does not "
                                  "carry; the frequency-domain ride (without [ride.simulation]) gives the "
                                  "lateral one");
    } else {
      throw std::invalid_argument("ride simulation: output '" + output.name + "': " + to_string(output.kind) + " " +
                                  to_string(output.axis) +
                                  " is not built in the time domain yet (points, and vertical element deflections)");
    }
  }
  return rows;
}

}  // namespace railmodal::ride
