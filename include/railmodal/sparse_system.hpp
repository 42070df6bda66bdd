// railmodal — large models as sparse matrices: a train of many wagons, or M and K read from
// Matrix Market files, solved for their lowest modes with ARPACK (docs/solvers.md).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::SparseSystem train = railmodal::wagon_train(400);  // 2 000 DOFs
//     railmodal::ModalOptions options;
//     options.solver = railmodal::ModalSolver::arpack;
//     options.mode_count = 20;
//     railmodal::ModalResult lowest = railmodal::solve_modes(train, options);
//     std::cout << "lowest: " << lowest.modes.front().frequency_hz << " Hz\n";
//   }
#pragma once

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal {

/// M q̈ + C q̇ + K q = f with sparse M, C, K (SI) over `dofs`; no bodies (Dof::body is -1),
/// so modes are named after the DOF with the most kinetic energy.
struct SparseSystem {
  std::string name;  ///< for reports: the files read, or "train of 400 wagons"
  std::vector<Dof> dofs;
  Eigen::SparseMatrix<double> mass;
  Eigen::SparseMatrix<double> damping;
  Eigen::SparseMatrix<double> stiffness;
  int size() const { return static_cast<int>(dofs.size()); }
};

/// The dense LinearSystem of a sparse one (no bodies, no gravity stiffness, no track inputs).
LinearSystem to_linear_system(const SparseSystem& system);

/// A generated test model: a train of `wagons` bogie wagons in the vertical-longitudinal
/// plane, 5 DOFs each (`wagon<i>.body.longitudinal`, `.body.bounce`, `.body.pitch`,
/// `.bogie1.bounce`, `.bogie2.bounce`), so 400 wagons make 2 000 DOFs and 20 000 make 10⁵.
/// Each wagon: body 22 t empty plus a load of 0–58 t that varies from wagon to wagon (the
/// fractional parts of i·0.618..., so no two wagons are alike and frequencies are distinct),
/// pitch inertia m·(14 m)²/12; bogies of 4.8 t at ±4.5 m on primary springs of 12 MN/m to the
/// track; secondary springs of 4 MN/m with dampers of 30 kN·s/m between bogie and body.
/// Neighbouring bodies are joined at their ends (±7.5 m) by couplers of 20 MN/m along the
/// track and 0.2 MN/m vertically. Nothing holds the train along the track: one rigid-body
/// mode (λ = 0), so K is singular. Throws std::invalid_argument unless wagons ≥ 1.
SparseSystem wagon_train(int wagons);

}  // namespace railmodal
