// railmodal — the assembled linear system M q̈ + C q̇ + K q = f.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Vehicle v = railmodal::load_vehicle("data/vehicles/resort_car.toml");
//     railmodal::LinearSystem s = railmodal::assemble(v, railmodal::DofSet::vertical);
//     for (const auto& dof : s.dofs) std::cout << dof.label << "\n";  // body.bounce, ...
//     std::cout << "K(0,0) = " << s.stiffness(0, 0) << " N/m\n";
//   }
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/vehicle.hpp"

namespace railmodal {

/// Which motions to keep: vertical = bounce and pitch (and longitudinal, where a body frees
/// it); lateral = lateral, roll and yaw.
enum class DofSet { vertical, lateral, all };
const char* to_string(DofSet set);
std::optional<DofSet> dof_set_from_string(const std::string& word);

/// One degree of freedom: a motion of a body's reference point.
struct Dof {
  std::string label;  ///< "<body>.<motion>", e.g. "body.bounce", "bogie1.pitch", "body.longitudinal"
  int body = 0;       ///< index into the vehicle's bodies; -1 for matrices read from files
  Motion motion = Motion::bounce;
};

/// An element whose lower end rides on the track (a wheel, through its axlebox springs):
/// where a displacement of the track enters. An element on the ground that resists only
/// longitudinal motion (draw gear to the rest of the train) is not one. A track displacement u (longitudinal, lateral,
/// vertical, m) at `point` loads the degrees of freedom with
/// Q = load_per_displacement · u + load_per_velocity · u̇. An element standing on a wheelset
/// (Vehicle::wheelsets) is one too, for the longitudinal and vertical displacement, which the
/// wheelset's held motions pass on from the rail; its lateral column is zero, the rail's lateral
/// displacement acting through the wheel–rail contact that M, C and K do not hold (a source that
/// moves it is refused: see ExcitationSource::load).
struct TrackInput {
  int element = 0;        ///< index into vehicle.elements
  Eigen::Vector3d point;  ///< m, vehicle frame (x: along the track, forward)
  Eigen::MatrixXd load_per_displacement;  ///< n × 3, N/m and N·m/m
  Eigen::MatrixXd load_per_velocity;      ///< n × 3, N·s/m and N·m·s/m
};

/// A damper with a spring in series (Element::series_dampers) seen from the degrees of
/// freedom: with s = stretch · q the element's stretch along its direction and F the damper
/// force, the equations gain  M q̈ + C q̇ + K q + stretchᵀ F = f  and  Ḟ = k·(ṡ − F/c).
struct SeriesDamperRow {
  int element = 0;  ///< index into vehicle.elements
  Motion direction = Motion::longitudinal;
  Eigen::RowVectorXd stretch;  ///< 1 × n, m per unit of each degree of freedom
  double damping = 0.0;        ///< c, N·s/m
  double stiffness = 0.0;      ///< k, N/m
};

/// M, C, K in SI over `dofs`. K = elastic stiffness + gravity (preload) stiffness; the
/// gravity part is kept separately so reports can show what the preload takes away.
struct LinearSystem {
  std::vector<Dof> dofs;
  Eigen::MatrixXd mass;
  Eigen::MatrixXd damping;
  Eigen::MatrixXd stiffness;          ///< elastic + gravity
  Eigen::MatrixXd gravity_stiffness;  ///< part of `stiffness` due to gravity and preloads
  Vehicle vehicle;                    ///< what was assembled (bodies give names and geometry)
  std::vector<double> element_loads;  ///< static vertical load of each element, N (+ = compression)
  std::vector<TrackInput> track_inputs;  ///< the elements standing on the track, in element order
  /// Row k: the vertical displacement of element k's upper end relative to its lower end (up
  /// positive, m) per unit of each degree of freedom; for a track element the track's own
  /// displacement is to be subtracted. The compression of the element is minus this stretch.
  Eigen::MatrixXd element_vertical_map;
  /// The series spring–dampers of the elements, whose stretch has a component in the kept
  /// degrees of freedom. Not in M, C, K: see SeriesDamperRow.
  std::vector<SeriesDamperRow> series_dampers;

  int size() const { return static_cast<int>(dofs.size()); }
  /// Index of the DOF with this label, or -1.
  int index_of(const std::string& label) const;
};

/// Assemble M, C and K of a vehicle for the chosen motions.
///
/// Elements add stiffness at their points through rigid-body kinematics, so geometry alone
/// creates coupling: unequal springs or an off-centre CG couple bounce and pitch (two-axle
/// digest eq. (153)), a CG above the reference point couples lateral and roll through M.
/// Gravity stiffness treats every static force as a dead load: the weight at each CG and
/// each element's static load at its point. For a body pivoting about a point l below its CG
/// on springs loaded at that point's height, this is the −W·l of eqs. (156a) and (160b).
///
/// Throws std::invalid_argument for an inconsistent vehicle (unknown body in an element,
/// duplicate names, non-positive mass) and railmodal::NumericalError when the static
/// equilibrium under gravity has no solution (a body that nothing holds up).
LinearSystem assemble(const Vehicle& vehicle, DofSet set);

}  // namespace railmodal
