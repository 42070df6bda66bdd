// Metacentric height by static condensation of the elastic roll stiffness (eq. (235b)
// generalised: any number of spring stages and bodies between the body and the track).
#include <Eigen/Dense>
#include <stdexcept>

#include "railmodal/linear_system.hpp"
#include "railmodal/stability.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

LateralStability lateral_stability(const Vehicle& vehicle, const std::string& body_name) {
  LateralStability out;
  StageClock clock(&out.summary);
  const LinearSystem s = assemble(vehicle, DofSet::lateral);
  clock.lap("assemble");
  const Eigen::MatrixXd K = s.stiffness - s.gravity_stiffness;  // springs only
  const int roll = s.index_of(body_name + ".roll");
  if (roll < 0) throw std::invalid_argument("body '" + body_name + "' has no free roll motion");
  const int lateral = s.index_of(body_name + ".lateral");
  std::vector<int> others;
  for (int i = 0; i < s.size(); ++i)
    if (i != roll && i != lateral) others.push_back(i);
  double k = K(roll, roll);
  if (!others.empty()) {
    const int n = static_cast<int>(others.size());
    Eigen::MatrixXd Koo(n, n);
    Eigen::VectorXd Kor(n);
    for (int i = 0; i < n; ++i) {
      Kor(i) = K(others[i], roll);
      for (int j = 0; j < n; ++j) Koo(i, j) = K(others[i], others[j]);
    }
    // Directions nothing restrains carry no roll moment: the minimum-norm solve skips them.
    k -= Kor.dot(Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(Koo).solve(Kor));
  }
  const Body* body = nullptr;
  for (const auto& b : vehicle.bodies)
    if (b.name == body_name) body = &b;
  out.body = body_name;
  out.roll_stiffness = k;
  out.metacentric_height = k / (body->mass * vehicle.gravity);
  out.cg_height = body->centre_of_gravity.z() - body->reference_point.z();
  out.margin = out.metacentric_height - out.cg_height;
  clock.lap("condense");
  out.summary.analysis = "static lateral stability";
  out.summary.method = "roll stiffness of the elastic springs by static condensation, h = k/W (eq. (235b))";
  out.summary.checks.push_back({"d0 − h, m (≤ 0: the body returns, §2.6)", -out.margin, 0.0, out.margin >= 0.0});
  return out;
}

}  // namespace railmodal
