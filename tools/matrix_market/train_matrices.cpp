// railmodal_train_matrices WAGONS PREFIX: writes PREFIX_M.mtx, PREFIX_K.mtx and PREFIX_C.mtx
// of railmodal::wagon_train(WAGONS) (5 DOFs per wagon), large test models for
// `railmodal modes --solver arpack` and tools/benchmarks/compare_arpack.py.
#include <fstream>
#include <iostream>
#include <string>

#include "railmodal/railmodal.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: railmodal_train_matrices WAGONS PREFIX\n";
    return 2;
  }
  const railmodal::SparseSystem train = railmodal::wagon_train(std::stoi(argv[1]));
  std::vector<std::string> labels;
  for (const auto& dof : train.dofs) labels.push_back(dof.label);
  const std::string prefix = argv[2];
  for (const auto& [suffix, matrix] : {std::pair{"_M.mtx", &train.mass}, std::pair{"_K.mtx", &train.stiffness},
                                       std::pair{"_C.mtx", &train.damping}}) {
    std::ofstream out(prefix + suffix);
    railmodal::write_matrix_market(out, *matrix, true, std::string(suffix) == "_M.mtx" ? labels : std::vector<std::string>{});
    if (!(out << std::flush)) {
      std::cerr << prefix << suffix << ": error: cannot write\n";
      return 5;
    }
  }
  return 0;
}
