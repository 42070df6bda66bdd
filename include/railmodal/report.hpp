// railmodal — writing modal results for people (table) and programs (CSV, JSON).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/fette_car.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::all);
//     auto result = railmodal::solve_modes(system);
//     railmodal::write_modes(std::cout, system, result, railmodal::OutputFormat::table);
//   }
#pragma once

#include <ostream>
#include <string>

#include "railmodal/damped_modal.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/output_format.hpp"

namespace railmodal {

/// Writes table, csv or json (std::invalid_argument for markdown and html). table: one row
/// per mode (index, name, Hz, s, rad/s, centre of oscillation) and the mode shapes below;
/// csv: one row per mode with one column per DOF; json: {"vehicle", "dofs", "modes":
/// [{"index", "kind", "frequency_hz", "period_s", "omega_rad_s", "divergence_rate_per_s",
/// "name", "stable", "repeated", "centre_of_oscillation" ({"about", "body", "x_m" or "z_m"}:
/// CentreOfOscillation::position, in the vehicle frame, z_m up from the axle plane), "residual", "shape": {label:
/// value}}], "condensed", "max_residual", "orthonormality_error"}. JSON also holds "solver":
/// {"name", and for ARPACK "shift", "factorisation", "requested", "subspace_size", "restarts",
/// "operator_applications", "runs", "count_checked"}. ModalResult::notes, when there are any,
/// are "note: ..." lines under the solver line (table), "# note: ..." lines before the heading
/// (csv) and "notes": [...] (json).
void write_modes(std::ostream& out, const LinearSystem& system, const ModalResult& result,
                 OutputFormat format);

/// Damped modes; writes table, csv or json (std::invalid_argument for markdown and html).
/// table: one row per mode (index, name, f_d, ζ, f_n, the undamped f_0, stability, a remark
/// for overdamped, critical, divergent, first-order and rigid-body modes); csv: the same with
/// the eigenvalues; json: {"vehicle", "dofs", "modes": [{"index", "name", "kind", "stable",
/// "eigenvalues": [[re, im]], "damped_frequency_hz", "damping_ratio", "natural_frequency_hz",
/// "undamped_mode", "undamped_frequency_hz", "decay_rate_per_s", "residual", "shape": {label:
/// [re, im]}}], "condensed", "first_order", "stable", "max_residual"}; absent quantities are
/// null. The undamped result's notes (ModalResult::notes) are written as write_modes writes them.
void write_damped_modes(std::ostream& out, const LinearSystem& system, const DampedModalResult& result,
                        OutputFormat format);
/// The same for a model without a LinearSystem (a SparseSystem): `title` names it. Writes
/// table, csv or json.
void write_modes(std::ostream& out, const std::string& title, const ModalResult& result, OutputFormat format);

}  // namespace railmodal
