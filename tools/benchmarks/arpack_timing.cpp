// The C++ half of compare_arpack.py: reads M and K (Matrix Market), times
// railmodal::solve_modes with ARPACK for the N lowest modes, prints JSON
// {"dofs", "read_s", "solve_s", "solve_cpu_s", "shift", "operator_applications",
// "max_residual", "eigenvalues"} to stdout (solve_cpu_s: the processor time of the solve, which
// a shared, loaded machine still measures fairly).
// Options: --tolerance T --ncv K (ARPACK's tol and subspace size), --shift S.
#include <chrono>
#include <ctime>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "railmodal/railmodal.hpp"

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: arpack_timing M.mtx K.mtx N [--tolerance T] [--ncv K] [--shift S]\n";
    return 2;
  }
  railmodal::ModalOptions options;
  options.solver = railmodal::ModalSolver::arpack;
  options.mode_count = std::stoi(argv[3]);
  options.max_residual = 1.0;  // loose tolerances are measured here, not rejected
  for (int i = 4; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--tolerance") options.arpack.tolerance = std::stod(argv[i + 1]);
    else if (key == "--ncv") options.arpack.subspace_size = std::stoi(argv[i + 1]);
    else if (key == "--shift") options.arpack.shift = std::stod(argv[i + 1]);
  }
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const railmodal::SparseSystem system = railmodal::to_sparse_system(railmodal::load_matrix_model(argv[1], argv[2]));
  const auto t1 = clock::now();
  const std::clock_t cpu = std::clock();
  const railmodal::ModalResult result = railmodal::solve_modes(system, options);
  const double solve_cpu = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
  const auto t2 = clock::now();
  nlohmann::json out;
  out["dofs"] = system.size();
  out["read_s"] = std::chrono::duration<double>(t1 - t0).count();
  out["solve_s"] = std::chrono::duration<double>(t2 - t1).count();
  out["solve_cpu_s"] = solve_cpu;
  out["shift"] = result.solver.shift;
  out["operator_applications"] = result.solver.operator_applications;
  out["max_residual"] = result.max_residual;
  out["eigenvalues"] = nlohmann::json::array();
  for (const auto& m : result.modes) out["eigenvalues"].push_back(m.eigenvalue);
  std::cout << out.dump() << "\n";
  return 0;
}
