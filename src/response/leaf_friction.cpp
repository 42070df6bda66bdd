// Leaf-spring friction in the frequency domain: the work it does against a mode (for the
// resonance criterion) and, when a user asks for it, an equivalent viscous damper.
//
// The series model, the same as the simulation's (src/simulate/nonlinear_elements.cpp): a leaf
// with friction force T = φ·P (P its static load; 1 ± φ ≈ 1, as the book's criterion takes it,
// bogie-wagons-forced digest §2.8 and E4) in series with elastic stages of series stiffness k_c,
// the pair stretched harmonically by X. At each reversal the leaf holds while the force through
// the pair crosses its band of width 2T, which the coils alone take: a stretch of 2T/k_c. The
// rest of the half-cycle's travel, 2X − 2T/k_c, is shared by the stages in series, the leaf
// taking share = k_e/c_l of it (k_e the element's series stiffness, c_l the leaf's). So the leaf
// slides share·(X − T/k_c) either way of its mean, and friction dissipates per cycle
//     W(X) = 4T·share·(X − T/k_c)   for X > T/k_c, and nothing below (the leaf never slips).
// A leaf alone (k_c → ∞) gives the book's 4T·X (Den Hartog). The growth criterion compares
// slopes, πF₀ against dW/dA = 4T·share·|d| per unit modal amplitude A: the hold costs a fixed
// stretch, not a rate, so a resonance that friction does not stop grows without bound as for
// the leaf alone. One that it stops cannot grow past
//     πF₀·A = Σ 4T·share·(|d|·A − T/k_c),
// the friction-limited amplitude, an upper bound (conservative), not the amplitude it settles
// at: this balance keeps the damping of the hysteresis loop but not its stiffening (while the
// leaf holds the pair is as stiff as the coils, so the in-phase stiffness rises from k_e toward
// k_c as the stretch falls toward T/k_c), which detunes the resonance. A single mass on a leaf
// over a coil driven over rail joints settles 4–40 % below it (tests/validation/
// friction_decay_test.cpp, FrictionLimitedAmplitude; 34–90 % under a pure harmonic force).
// A describing function would add that in-phase stiffness.
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "railmodal/response.hpp"
#include "response/friction_damping.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Friction force R = φ × load of the friction stage of element k (one at most: the vehicle
// reader refuses two), the stage's share
// k_element/k_stage of the element's stretch (in series every stage carries the element's force),
// and the stretch R/k_c the other stages take alone while it holds (0 for a stage alone).
template <typename Visit>
void for_each_friction_stage_of(const LinearSystem& system, size_t k, Visit visit) {
  const Element& e = system.vehicle.elements[k];
  const double k_element = series_stiffness(e.vertical_stages);
  // A leaf in tension carries no friction (the law is φ × a compressive load), as in the simulation.
  if (!(k_element > 0.0) || !(system.element_loads[k] > 0.0)) return;
  for (const SpringStage& s : e.vertical_stages)
    if (s.relative_friction > 0.0) {
      double others_flexibility = 0.0;  // 1/k_c of the other stages in series
      for (const SpringStage& o : e.vertical_stages)
        if (&o != &s) others_flexibility += 1.0 / (o.stiffness * o.count);
      const double friction = s.relative_friction * system.element_loads[k];
      visit(friction, k_element / (s.stiffness * s.count), friction * others_flexibility);
    }
}

// The same over every element; `visit(k, friction, share)`.
template <typename Visit>
void for_each_friction_stage(const LinearSystem& system, Visit visit) {
  for (size_t k = 0; k < system.vehicle.elements.size(); ++k)
    for_each_friction_stage_of(system, k, [&](double friction, double share, double) { visit(k, friction, share); });
}

}  // namespace

// A real shape is the in-phase case of the complex one (|x + 0i| = |x| exactly).
double modal_friction_work(const LinearSystem& system, const Eigen::VectorXd& shape) {
  return response::modal_friction_work(system, Eigen::VectorXcd(shape.cast<std::complex<double>>()));
}

// One weighing of the friction work: the stages found for this one call.
double response::modal_friction_work(const LinearSystem& system, const Eigen::VectorXcd& shape) {
  return modal_friction_work(friction_stages(system), shape);
}

response::FrictionStages response::friction_stages(const LinearSystem& system) {
  FrictionStages out;
  out.stages.reserve(system.vehicle.elements.size());      // a stage an element at most
  out.entries.reserve(2 * system.vehicle.elements.size());  // a suspension's row moves about two DOFs
  for_each_friction_stage(system, [&](size_t k, double friction, double share) {
    FrictionStage stage{k, friction, share, out.entries.size(), 0};
    for (int d = 0; d < system.element_vertical_map.cols(); ++d)
      if (system.element_vertical_map(static_cast<Eigen::Index>(k), d) != 0.0)
        out.entries.push_back({d, system.element_vertical_map(static_cast<Eigen::Index>(k), d)});
    stage.end = out.entries.size();
    out.stages.push_back(stage);
  });
  return out;
}

double response::modal_friction_work(const FrictionStages& stages, const Eigen::VectorXcd& shape) {
  double work = 0.0;
  for (const FrictionStage& s : stages.stages) {
    // The stretch δ = row·ψ over the row's nonzero entries, in the row's order: the terms a
    // zero entry adds are zeros, so |δ| is the dense product's to the bit.
    std::complex<double> stretch = 0.0;
    for (size_t e = s.begin; e < s.end; ++e) stretch += stages.entries[e].second * shape(stages.entries[e].first);
    work += s.friction * std::abs(s.share * stretch);
  }
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
  for_each_friction_stage_of(system, element, [&](double friction, double share, double hold) {
    // With the element stretching X the leaf slides share·(X − hold) and friction dissipates
    // 4R·share·(X − hold) per cycle (see the top); a damper across the element dissipates πcωX².
    c += 4.0 * friction * share / (kPi * omega * stretch) * std::max(1.0 - hold / stretch, 0.0);
  });
  return c;
}

double response::leaf_hold_stretch(const LinearSystem& system, std::size_t element) {
  double hold = 0.0;
  for_each_friction_stage_of(system, element, [&](double, double, double h) { hold = std::max(hold, h); });
  return hold;
}

LinearSystem with_equivalent_friction_damping(const LinearSystem& system, double omega,
                                              const std::vector<double>& stretch_per_element) {
  if (!(omega > 0.0)) throw std::invalid_argument("equivalent friction damping needs a positive frequency");
  std::vector<double> damping(system.vehicle.elements.size(), 0.0);
  for (size_t k = 0; k < damping.size() && k < stretch_per_element.size(); ++k)
    damping[k] = response::equivalent_friction_damping(system, k, omega, stretch_per_element[k]);
  return response::with_element_vertical_dampers(system, damping);
}

double response::friction_force_share(const LinearSystem& system, std::size_t element) {
  double sum = 0.0;
  for_each_friction_stage_of(system, element, [&](double friction, double share, double) { sum += friction * share; });
  return sum;
}

LinearSystem response::with_element_vertical_dampers(const LinearSystem& system, const std::vector<double>& damping) {
  LinearSystem out = system;
  for (size_t k = 0; k < system.vehicle.elements.size() && k < damping.size(); ++k) {
    const double c = damping[k];
    if (c == 0.0) continue;
    const Eigen::RowVectorXd row = system.element_vertical_map.row(k);
    out.damping += c * row.transpose() * row;
    for (auto& input : out.track_inputs)
      if (input.element == static_cast<int>(k)) input.load_per_velocity.col(2) += c * row.transpose();
  }
  return out;
}

}  // namespace railmodal
