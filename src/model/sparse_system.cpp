// The dense copy of a sparse model, for the dense modal solver.
#include "railmodal/sparse_system.hpp"

namespace railmodal {

LinearSystem to_linear_system(const SparseSystem& system) {
  LinearSystem dense;
  dense.dofs = system.dofs;
  dense.mass = Eigen::MatrixXd(system.mass);
  dense.damping = system.damping.size() > 0 ? Eigen::MatrixXd(system.damping)
                                            : Eigen::MatrixXd::Zero(system.size(), system.size());
  dense.stiffness = Eigen::MatrixXd(system.stiffness);
  dense.gravity_stiffness = Eigen::MatrixXd::Zero(system.size(), system.size());
  dense.vehicle.name = system.name;
  return dense;
}

}  // namespace railmodal
