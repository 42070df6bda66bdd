// Metacentric height by static condensation of the elastic roll stiffness (eq. (235b)
// generalised: any number of spring stages and bodies between the body and the track).
#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

#include "model/assembly.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/stability.hpp"
#include "solve/lateral_stability.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

LateralStability lateral_stability(const Vehicle& vehicle, const std::string& body_name) {
  LateralStability out;
  StageClock clock(&out.summary);
  // The stiffness alone: the damping, track inputs and vehicle copy of a full assembly would
  // cost as much again.
  const LinearSystem s = model::assemble_stiffness(vehicle, DofSet::lateral);
  clock.lap("assemble");
  solve::condense_roll(vehicle, s, body_name, &out);
  clock.lap("condense");
  return out;
}

void solve::condense_roll(const Vehicle& vehicle, const LinearSystem& s, const std::string& body_name,
                          LateralStability* result) {
  LateralStability& out = *result;
  // This thread's matrices and list, their storage kept between calls (a study condenses every
  // variant's roll): the same values as fresh ones.
  thread_local Eigen::MatrixXd K, Koo;
  thread_local Eigen::VectorXd Kor;
  thread_local std::vector<int> others;
  K = s.stiffness - s.gravity_stiffness;  // springs only
  const int roll = s.index_of(body_name + ".roll");
  if (roll < 0) throw std::invalid_argument("body '" + body_name + "' has no free roll motion");
  const int lateral = s.index_of(body_name + ".lateral");
  others.clear();
  others.reserve(static_cast<size_t>(s.size()));
  for (int i = 0; i < s.size(); ++i)
    if (i != roll && i != lateral) others.push_back(i);
  double k = K(roll, roll);
  if (!others.empty()) {
    const int n = static_cast<int>(others.size());
    Koo.resize(n, n);
    Kor.resize(n);
    for (int i = 0; i < n; ++i) {
      Kor(i) = K(others[i], roll);
      for (int j = 0; j < n; ++j) Koo(i, j) = K(others[i], others[j]);
    }
    // Directions nothing restrains carry no roll moment: the minimum-norm solve skips them.
    // This thread's decomposition, kept as the matrices above: the same factorisation.
    thread_local Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
    cod.compute(Koo);
    k -= Kor.dot(cod.solve(Kor));
  }
  const Body* body = nullptr;
  for (const auto& b : vehicle.bodies)
    if (b.name == body_name) body = &b;
  out.body = body_name;
  out.roll_stiffness = k;
  out.metacentric_height = k / (body->mass * vehicle.gravity);
  out.cg_height = body->centre_of_gravity.z() - body->reference_point.z();
  out.margin = out.metacentric_height - out.cg_height;
  out.summary.analysis = "static lateral stability";
  out.summary.method = "roll stiffness of the elastic springs by static condensation, h = k/W (eq. (235b))";
  // Its one check written in place (a kept result's name reuses its storage).
  out.summary.checks.resize(1);
  Check& check = out.summary.checks.front();
  check.name = "d0 − h, m (≤ 0: the body returns, §2.6)";
  check.value = -out.margin;
  check.limit = 0.0;
  check.passed = out.margin >= 0.0;
}

}  // namespace railmodal
