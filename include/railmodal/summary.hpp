// railmodal — what an analysis did: the quantity it computed, by which method, the checks it
// made of its answer (with their values) and the wall time of each stage. Every analysis
// result carries one (ModalResult::solver extends it), filled on every call; no report or
// output format writes it (times vary from run to run).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto system = railmodal::assemble(railmodal::load_vehicle("data/vehicles/manchester_benchmark_coach.toml"),
//                                       railmodal::DofSet::all);
//     railmodal::DampedModalResult r = railmodal::solve_damped_modes(system);
//     std::cout << r.summary.brief() << "\n";
//     // damped modes by QR of the balanced state matrix on the undamped modal basis (Eigen), roots
//     // matched to undamped modes by their energy: 1 of 1 checks passed; 0.0021 s (undamped modes
//     // 0.0009 s, state-space eigenvalues 0.0008 s, matching and shapes 0.0004 s)
//     for (const railmodal::Check& check : r.summary.checks)
//       if (!check.passed) return 1;
//   }
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace railmodal {

/// One check an analysis made of its answer.
struct Check {
  std::string name;     ///< what was checked, e.g. "max relative residual"
  double value = 0.0;   ///< what was found (in the unit the name gives; counts as numbers)
  /// The bound `value` was held to: passed means value ≤ limit. +∞: reported, not bounded.
  double limit = std::numeric_limits<double>::infinity();
  bool passed = true;
};

/// The wall time of one stage of an analysis (std::chrono::steady_clock).
struct StageTiming {
  std::string stage;     ///< e.g. "eigensolve"
  double seconds = 0.0;  ///< s, ≥ 0
};

struct AnalysisSummary {
  std::string analysis;  ///< what was computed, e.g. "undamped modes"
  std::string method;    ///< how, e.g. "dense: Cholesky of M and symmetric QR (Eigen)"
  std::vector<Check> checks;
  /// In the order they ran; they do not overlap, so their sum is at most the call's wall time.
  std::vector<StageTiming> stages;
  double total_seconds() const;  ///< Σ stages, s
  bool passed() const;           ///< every check passed
  /// One line for a log: "<analysis> by <method>: N checks passed; T s (stage t s, ...)".
  std::string brief() const;
};

}  // namespace railmodal
