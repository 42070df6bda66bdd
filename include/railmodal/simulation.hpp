// Time-domain simulation of an assembled vehicle running over its excitation sources.
//
// The linear path integrates M ẍ + C ẋ + K x = F(t) exactly for a load that is linear over
// each step (the state transition e^{AΔt} and its first-order-hold input integrals, from one
// matrix exponential; Van Loan 1978), so the only error is that of sampling F(t) at the step:
// O(Δt²) for smooth forcing, none for free motion. Massless DOFs follow statically.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "railmodal/excitation.hpp"
#include "railmodal/linear_system.hpp"

namespace railmodal {

/// A DOF displaced and/or moving at t = 0 (the book's drop tests release a load from rest
/// at a displaced position).
struct InitialCondition {
  std::string dof;          ///< DOF label, e.g. "body.bounce"
  double displacement = 0.0;  ///< m or rad
  double velocity = 0.0;      ///< m/s or rad/s
};

struct SimulationOptions {
  double speed = 0.0;      ///< m/s, constant (> 0 when there are sources)
  double duration = 0.0;   ///< s
  double time_step = 0.0;  ///< s, integration and output step
  std::vector<InitialCondition> initial;
};

/// Sampled response: one row per time, one column per DOF.
struct TimeHistory {
  std::vector<std::string> labels;  ///< DOF labels, the columns
  Eigen::VectorXd time;             ///< s
  Eigen::MatrixXd displacement;     ///< m or rad
  Eigen::MatrixXd velocity;         ///< m/s or rad/s
};

/// Linear scene: the sources enter through their harmonic loads Σ_k Re(Q_k e^{iω_k t}) (as in
/// the harmonic response), the vehicle's viscous dampers through C. Throws std::invalid_argument
/// for bad options or initial conditions on unknown or massless DOFs.
TimeHistory simulate_linear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                            const SimulationOptions& options);

}  // namespace railmodal
