// Reading what every body needs, whatever form the file takes.
#pragma once

#include <Eigen/Core>

#include "input/table_reader.hpp"

namespace railmodal::input {

/// `mass` (a mass) or `weight` (a force, divided by the vehicle's gravity): exactly one.
double read_mass(TableReader& t, double gravity);

/// `inertia = {roll, pitch, yaw}` (kg·m², or "kgf*cm*s^2") or `radius_of_gyration =
/// {roll, pitch, yaw}` (lengths, about the CG): exactly one. Missing components are zero
/// (a massless rotation, condensed statically).
Eigen::Vector3d read_inertia(TableReader& t, double mass);

/// `free = ["longitudinal"]`: whether the body frees its longitudinal motion, the one motion
/// held unless freed (false when absent).
bool read_longitudinal_free(TableReader& t);

}  // namespace railmodal::input
