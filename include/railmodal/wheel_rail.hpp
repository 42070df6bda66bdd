// railmodal — the linearised wheel–rail contact: Hertz's contact ellipse, Kalker's creep
// coefficients, and the contact terms a vehicle's wheelsets add to its equations of motion
// (docs/stability.md derives every term and cites its sources).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::HertzContactInput in;
//     in.wheel_load = 50e3;             // N on one wheel
//     in.rail_head_radius = 0.3;        // m
//     auto ellipse = railmodal::hertz_contact(in, 0.46);  // rolling radius 0.46 m
//     auto c = railmodal::kalker_coefficients(ellipse.a / ellipse.b, in.poisson_ratio);
//     std::cout << "a = " << ellipse.a * 1e3 << " mm, b = " << ellipse.b * 1e3 << " mm, C11 = " << c.c11 << "\n";
//
//     auto vehicle = railmodal::load_vehicle("data/vehicles/wheelset_on_springs.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::lateral);
//     auto contact = railmodal::contact_matrices(system);
//     std::cout << "f22 = " << contact.wheelsets[0].creep.f22 << " N\n";
//   }
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal {

/// The contact ellipse of Hertz's theory.
struct HertzContact {
  double a = 0.0;  ///< semi-axis in the rolling direction, m
  double b = 0.0;  ///< semi-axis across the rail, m
  double max_pressure = 0.0;  ///< p0 = 3N/(2πab), Pa
  double approach = 0.0;      ///< the normal approach of the two bodies, m
};

/// Hertz's contact ellipse of one wheel on its rail under the wheel load `input.wheel_load`
/// (which must be set), the wheel's rolling radius `rolling_radius` and the transverse radii of
/// `input`. Throws std::invalid_argument for a load or radius out of range, or for curvatures
/// whose sum is not positive in both directions (no point contact).
HertzContact hertz_contact(const HertzContactInput& input, double rolling_radius);

/// Kalker's dimensionless creepage and spin coefficients of linear theory.
struct KalkerCoefficients {
  double c11 = 0.0, c22 = 0.0, c23 = 0.0, c33 = 0.0;
};

/// Kalker's coefficients for the semi-axis ratio a/b and Poisson's ratio ν, interpolated in
/// his table as tabulated (docs/stability.md says how, and where the table comes from).
/// Throws std::invalid_argument outside the table (0.1 ≤ a/b ≤ 10, 0 ≤ ν ≤ 0.5).
KalkerCoefficients kalker_coefficients(double a_over_b, double poisson_ratio);

/// f11, f22, f23, f33 of a contact ellipse and its material.
CreepCoefficients creep_coefficients(const HertzContact& ellipse, double youngs_modulus, double poisson_ratio);

/// What one wheelset's contact resolved to: the figures every term was built from.
struct ResolvedContact {
  std::string body;          ///< the wheelset's body
  double axle_load = 0.0;    ///< W, N: the wheelset's weight and the static loads it carries
  /// Where W came from: "given" (WheelRailContact::axle_load), "static loads" (the wheelset's
  /// weight and the static loads of elements standing on it) or "own weight only" (nothing
  /// stands on it: W is the wheelset's weight alone, usually far below a real axle load).
  std::string axle_load_source;
  double conicity = 0.0;     ///< λ
  double contact_angle_parameter = 0.0;  ///< ε
  double roll_parameter = 0.0;           ///< σ
  double rolling_radius = 0.0;           ///< r0, m
  double contact_half_spacing = 0.0;     ///< l0, m
  CreepCoefficients creep;               ///< per wheel
  std::optional<HertzContact> ellipse;   ///< when the creep coefficients were computed
  double klingel_wavelength = 0.0;       ///< 2π√(r0·l0/λ), m (infinite at zero conicity)
};

/// The terms the wheelsets' contact adds to a system's equations of motion, over its degrees
/// of freedom: M q̈ + (C + C_c/V + V·G) q̇ + (K + K_c) q = 0 at speed V.
struct ContactMatrices {
  Eigen::MatrixXd creep_damping;  ///< C_c, N·m/s… per unit speed: the creep damping is C_c / V
  Eigen::MatrixXd gyroscopic;     ///< G: the gyroscopic damping is V·G
  Eigen::MatrixXd stiffness;      ///< K_c: creep and gravitational stiffness (not symmetric)
  std::vector<ResolvedContact> wheelsets;  ///< in the order of vehicle.wheelsets
};

/// The contact terms of `system.vehicle.wheelsets` over `system.dofs` (an assembly of the
/// lateral motions, or of all). `conicity`, when given, replaces every wheelset's equivalent
/// conicity (and the ε and σ that default from it): the design curve of critical speed against
/// conicity. Throws std::invalid_argument when the vehicle has no wheelsets, a wheelset's body
/// is not in the system with its lateral and yaw motions free, or a contact value is out of
/// range (naming the wheelset and the value).
ContactMatrices contact_matrices(const LinearSystem& system, std::optional<double> conicity = std::nullopt);

}  // namespace railmodal
