// Leaf-spring friction against a mode: the work it does per unit modal amplitude.
#include <cmath>

#include "model/rigid_body.hpp"
#include "railmodal/response.hpp"

namespace railmodal {

double modal_friction_work(const LinearSystem& system, const Eigen::VectorXd& shape) {
  const Vehicle& v = system.vehicle;
  // The shape in each body's five motions (held motions are zero).
  std::vector<model::BodyVector> q(v.bodies.size(), model::BodyVector::Zero());
  for (int d = 0; d < system.size(); ++d) q[system.dofs[d].body](static_cast<int>(system.dofs[d].motion)) = shape(d);
  auto body_of = [&](const std::string& name) {
    for (size_t b = 0; b < v.bodies.size(); ++b)
      if (v.bodies[b].name == name) return static_cast<int>(b);
    return -1;
  };
  double work = 0.0;
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    const double k_element = series_stiffness(e.vertical_stages);
    if (!(k_element > 0.0)) continue;
    double stretch = 0.0;  // vertical, upper relative to lower
    const int up = body_of(e.upper), low = body_of(e.lower);
    stretch += model::point_map(v.bodies[up], e.point).row(2).dot(q[up]);
    if (low >= 0) stretch -= model::point_map(v.bodies[low], e.point).row(2).dot(q[low]);
    const double load = std::abs(system.element_loads[k]);
    for (const SpringStage& s : e.vertical_stages) {
      if (!(s.relative_friction > 0.0)) continue;
      // In series, each stage takes the element's force: its stretch is k_element/k_stage of it.
      const double stage_stretch = stretch * k_element / (s.stiffness * s.count);
      work += s.relative_friction * load * std::abs(stage_stretch);
    }
  }
  return work;
}

}  // namespace railmodal
