// The saturation of the creep forces at the friction limit: Shen, Hedrick and Elkins' law
// (docs/stability.md, "The nonlinear critical speed").
#pragma once

#include "model/wheelset_creepage.hpp"

namespace railmodal::stability {

/// Kalker's linear forces scaled so that their resultant follows Johnson and Vermeulen's cubic
/// up to 3μN and stays at μN beyond (Shen, Hedrick and Elkins 1983): with F = |(Fx, Fy)| of the
/// linear law and u = F/(μN), the resultant is μN·(u − u²/3 + u³/27) for u < 3 and μN beyond;
/// Fx, Fy and the spin moment Mz are all scaled by that resultant over F.
model::WheelContactForces saturated_creep_forces(const CreepCoefficients& creep, const model::WheelCreepage& creepage,
                                                 double friction_limit);

}  // namespace railmodal::stability
