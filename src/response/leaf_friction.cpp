// Leaf-spring friction in the frequency domain: the work it does against a mode (for the
// resonance criterion) and, when a user asks for it, an equivalent viscous damper.
#include <cmath>
#include <complex>
#include <stdexcept>

#include "railmodal/response.hpp"
#include "response/friction_damping.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Friction force R = φ × load of each friction stage of element k, and the stage's share
// k_element/k_stage of the element's stretch (in series every stage carries the element's force).
template <typename Visit>
void for_each_friction_stage_of(const LinearSystem& system, size_t k, Visit visit) {
  const Element& e = system.vehicle.elements[k];
  const double k_element = series_stiffness(e.vertical_stages);
  if (!(k_element > 0.0)) return;
  for (const SpringStage& s : e.vertical_stages)
    if (s.relative_friction > 0.0)
      visit(s.relative_friction * std::abs(system.element_loads[k]), k_element / (s.stiffness * s.count));
}

// The same over every element; `visit(k, friction, share)`.
template <typename Visit>
void for_each_friction_stage(const LinearSystem& system, Visit visit) {
  for (size_t k = 0; k < system.vehicle.elements.size(); ++k)
    for_each_friction_stage_of(system, k, [&](double friction, double share) { visit(k, friction, share); });
}

}  // namespace

double modal_friction_work(const LinearSystem& system, const Eigen::VectorXd& shape) {
  double work = 0.0;
  for_each_friction_stage(system, [&](size_t k, double friction, double share) {
    work += friction * std::abs(share * system.element_vertical_map.row(k).dot(shape));
  });
  return work;
}

double response::modal_friction_work(const LinearSystem& system, const Eigen::VectorXcd& shape) {
  double work = 0.0;
  for_each_friction_stage(system, [&](size_t k, double friction, double share) {
    work += friction * std::abs(share * system.element_vertical_map.row(k).cast<std::complex<double>>().dot(shape));
  });
  return work;
}

bool has_leaf_friction(const LinearSystem& system) {
  bool any = false;
  for_each_friction_stage(system, [&](size_t, double, double) { any = true; });
  return any;
}

LinearSystem with_equivalent_friction_damping(const LinearSystem& system, double omega, double stretch_amplitude) {
  if (!(omega > 0.0) || !(stretch_amplitude > 0.0))
    throw std::invalid_argument("equivalent friction damping needs a positive frequency and amplitude");
  return with_equivalent_friction_damping(system, omega,
                                          std::vector<double>(system.vehicle.elements.size(), stretch_amplitude));
}

double response::equivalent_friction_damping(const LinearSystem& system, std::size_t element, double omega,
                                             double stretch) {
  if (!(omega > 0.0) || !(stretch > 0.0)) return 0.0;
  double c = 0.0;
  for_each_friction_stage_of(system, element, [&](double friction, double share) {
    // With the element stretching X the stage stretches share·X and friction dissipates
    // 4R·share·X per cycle; a damper across the element dissipates πcωX²: c = 4R·share/(πωX).
    c += 4.0 * friction * share / (kPi * omega * stretch);
  });
  return c;
}

LinearSystem with_equivalent_friction_damping(const LinearSystem& system, double omega,
                                              const std::vector<double>& stretch_per_element) {
  if (!(omega > 0.0)) throw std::invalid_argument("equivalent friction damping needs a positive frequency");
  LinearSystem out = system;
  const Vehicle& v = system.vehicle;
  for (size_t k = 0; k < v.elements.size() && k < stretch_per_element.size(); ++k) {
    const double c = response::equivalent_friction_damping(system, k, omega, stretch_per_element[k]);
    if (c == 0.0) continue;
    const Eigen::RowVectorXd row = system.element_vertical_map.row(k);
    out.damping += c * row.transpose() * row;
    for (auto& input : out.track_inputs)
      if (input.element == static_cast<int>(k)) input.load_per_velocity.col(2) += c * row.transpose();
  }
  return out;
}

}  // namespace railmodal
