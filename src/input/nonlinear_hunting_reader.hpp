// The [nonlinear_hunting] table of a scene: what `railmodal hunting` runs, with the effects it
// simulates named by their sub-tables.
#pragma once

#include "input/table_reader.hpp"
#include "railmodal/nonlinear_hunting.hpp"

namespace railmodal::input {

/// Reads [nonlinear_hunting] (`t`): the ramp (start_speed, end_speed, ramp_rate, disturbance),
/// the convergence settings, and the effects [nonlinear_hunting.creep_saturation] (law,
/// friction_coefficient, wheel_load, contact_angle) and [nonlinear_hunting.flange_contact]
/// (clearance, stiffness); an effect without its table is not simulated. Throws InputError at the
/// key.
NonlinearHuntingOptions read_nonlinear_hunting(TableReader t);

}  // namespace railmodal::input
