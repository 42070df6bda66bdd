// Leaf friction in random ride: the statistical linearisation of a Coulomb force under a
// Gaussian relative velocity, iterated to consistency with the response it produces.
//
// Why not the harmonic equivalence of the periodic analyses (c = 4F/(πωX)): under a random
// input there is no single ω or amplitude; the least-mean-square replacement of F·sgn(v) by
// c·v for a Gaussian v (Roberts & Spanos, Random Vibration and Statistical Linearization,
// 1990, §5.2 and §6.2: the equivalent linear coefficient E[∂g/∂v] = 2F·p_v(0) = F√(2/π)/σ_v)
// depends on the RMS velocity only, and the response's σ_v depends on c: hence the iteration.
// Caughey (J. Acoust. Soc. Am. 35(11), 1963, "Equivalent linearization techniques") gives the
// same coefficient. What it leaves out: the hold of a leaf in series with coil springs (the
// harmonic model's T/k_c, src/response/leaf_friction.cpp), which lowers the dissipation at small
// motions; so this c is an upper bound where σ_v·(time) is comparable to the hold stretch.
#include "ride/ride_friction.hpp"

#include <algorithm>
#include <cmath>

#include "railmodal/response.hpp"
#include "response/friction_damping.hpp"

namespace railmodal::ride {

std::vector<FrictionElement> friction_elements(const LinearSystem& system) {
  std::vector<FrictionElement> out;
  for (size_t k = 0; k < system.vehicle.elements.size(); ++k) {
    const double force = response::friction_force_share(system, k);
    if (force > 0.0) out.push_back({static_cast<int>(k), force});
  }
  return out;
}

double gaussian_friction_damping(double force, double velocity_rms) {
  constexpr double kSqrtTwoOverPi = 0.79788456080286535588;
  return force * kSqrtTwoOverPi / std::max(velocity_rms, 1e-9);
}

// In x = log c the consistency is F(x) = log(F√(2/π)) − log σ(e^x) − x = 0. The plain
// iteration x ← x + F converges at the rate g = −d log σ/d log c, which nears 1 when friction
// dominates (the body locks onto the track and the stretch rate falls as 1/c): hundreds of
// passes. A secant step per element on F (the slope taken from its own last two passes; the
// elements couple only weakly through the body) converges superlinearly; a step is bounded to a
// factor e² in c, and a pass whose slope is not negative falls back to the plain step.
FrictionLinearisation linearise_friction(const LinearSystem& system, const std::vector<FrictionElement>& elements,
                                         double tolerance, int max_passes,
                                         const std::function<std::vector<double>(const std::vector<double>&)>& velocity_rms) {
  FrictionLinearisation out;
  out.damping.assign(system.vehicle.elements.size(), 0.0);
  const size_t count = elements.size();
  std::vector<double> x(count), previous_x(count), previous_f(count);
  std::vector<double> sigma(count, 0.01);
  for (size_t e = 0; e < count; ++e) x[e] = std::log(gaussian_friction_damping(elements[e].force, sigma[e]));
  while (out.passes < max_passes) {
    for (size_t e = 0; e < count; ++e) out.damping[elements[e].element] = std::exp(x[e]);
    const std::vector<double> next = velocity_rms(out.damping);
    ++out.passes;
    out.change = 0.0;
    for (size_t e = 0; e < count; ++e) {
      // An unbounded response (σ = ∞, no other damping) asks for more friction damping than this.
      const double s = std::isfinite(next[e]) ? next[e] : 100.0 * sigma[e];
      sigma[e] = s;
      const double f = std::log(gaussian_friction_damping(elements[e].force, s)) - x[e];
      out.change = std::max(out.change, std::abs(f));
      double step = f;
      const double slope = out.passes > 1 && x[e] != previous_x[e] ? (f - previous_f[e]) / (x[e] - previous_x[e]) : 0.0;
      if (slope < 0.0) step = -f / slope;
      previous_x[e] = x[e];
      previous_f[e] = f;
      x[e] += std::clamp(step, -2.0, 2.0);
    }
    // |F| is the relative mismatch of c and F√(2/π)/σ(c) (to first order, of σ itself).
    if (out.change <= tolerance) {
      out.converged = true;
      break;
    }
  }
  // The damping of the last solve: consistent with its σ to within `change`.
  for (size_t e = 0; e < count; ++e) out.damping[elements[e].element] = std::exp(previous_x[e]);
  return out;
}

}  // namespace railmodal::ride
