// Writes a vehicle's assembled M, K (and C when it has dampers) as Matrix Market files,
// labelled with its DOFs: how data/matrices/ was made, and a way to hand a wagon to other
// tools (scipy.io.mmread, FE packages).
//
//   railmodal_export_matrices data/vehicles/resort_car.toml vertical data/matrices/resort_car_vertical
//   → resort_car_vertical_M.mtx, resort_car_vertical_K.mtx
#include <fstream>
#include <iostream>

#include "railmodal/railmodal.hpp"

namespace {

// Symmetric storage when A is symmetric to round-off (assembly sums in different orders
// above and below the diagonal), general storage otherwise.
bool write(const std::string& path, const Eigen::MatrixXd& A, const std::vector<std::string>& labels) {
  const double asymmetry = (A - A.transpose()).cwiseAbs().maxCoeff();
  const bool symmetric = asymmetry <= 1e-14 * A.cwiseAbs().maxCoeff();
  const Eigen::MatrixXd stored = symmetric ? Eigen::MatrixXd(0.5 * (A + A.transpose())) : A;
  std::ofstream out(path);
  railmodal::write_matrix_market(out, stored.sparseView(), symmetric, labels);
  out.close();
  if (!out) std::cerr << path << ": error: cannot write the file\n";
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || !railmodal::dof_set_from_string(argv[2])) {
    std::cerr << "usage: railmodal_export_matrices VEHICLE.toml vertical|lateral|all PREFIX\n";
    return 2;
  }
  try {
    const auto system = railmodal::assemble(railmodal::load_vehicle(argv[1]), *railmodal::dof_set_from_string(argv[2]));
    std::vector<std::string> labels;
    for (const auto& dof : system.dofs) labels.push_back(dof.label);
    const std::string prefix = argv[3];
    bool ok = write(prefix + "_M.mtx", system.mass, labels) && write(prefix + "_K.mtx", system.stiffness, labels);
    if (ok && system.damping.cwiseAbs().maxCoeff() > 0.0) ok = write(prefix + "_C.mtx", system.damping, labels);
    return ok ? 0 : 5;
  } catch (const railmodal::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
