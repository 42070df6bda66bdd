// Reading what every body needs, whatever form the file takes.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "input/table_reader.hpp"
#include "railmodal/vehicle.hpp"

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

/// `bending = { ... }` (a `[body.bending]` table): the body's first vertical bending mode, a
/// free–free beam: `length`, optional `centre` (x; default the CG's), `damping_ratio`, and
/// either `bending_stiffness` (EI) with `mass_per_length`, or `frequency` with `modal_mass`
/// (mode shape 1 at the beam's ends) (docs/input.md, "Car-body bending"). None when absent.
std::optional<BodyBending> read_bending(TableReader& t);

/// `floor_height`: z of the body's floor, a length above the plane of the axles (the vehicle
/// frame's z, as `[draw_gear]`'s `height`; not above the bolster plane as the bogie template's
/// body `cg_height`), where the ride's default floor points lie. None when absent.
std::optional<double> read_floor_height(TableReader& t);

/// Fails at the body's `bending.length` when an element attached to `body` acts beyond the
/// ends of its bending beam (the beam is not there). Nothing when the body has no bending.
void check_bending_reach(TableReader& body_table, const Body& body, const std::vector<Element>& elements);

/// The wheel–rail contact keys of a wheelset table (`[[wheelset]]` or a template's
/// `[wheelset]`): rolling_radius, contact_half_spacing, conicity, the optional
/// contact_angle_parameter and roll_parameter, and exactly one of `creep = {f11, f22, f23,
/// f33}` and `hertz = {...}` (docs/input.md, "Wheelsets").
WheelRailContact read_contact(TableReader& t);

/// `spin_inertia`: the wheelset's moment of inertia about its axle (kg·m², ≥ 0; required, since
/// it sets the gyroscopic terms).
double read_spin_inertia(TableReader& t);

/// The motions a wheelset body holds: bounce, roll and pitch follow the rails in the linear model.
inline constexpr Motion kWheelsetHeld[] = {Motion::bounce, Motion::roll, Motion::pitch};

}  // namespace railmodal::input
