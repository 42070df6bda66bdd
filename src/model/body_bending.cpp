// The free–free Euler–Bernoulli beam's first bending mode, in closed form.
//
// The beam's deflection w(s) (s from one end, 0 ≤ s ≤ L) in a mode of frequency ω solves
// EI w'''' = m' ω² w with zero moment and shear at both ends (w'' = w''' = 0). With
// β⁴ = m' ω² L⁴ / EI, the solutions cosh, cos, sinh, sin of βs/L meet the four end conditions
// only where cos β · cosh β = 1; the first nonzero root is β₁ = 4.7300407449 (Thomson and
// Dahleh, "Theory of vibration with applications", 5th ed. 1998, Appendix D: free–free as
// clamped–clamped, β₁L = 4.7300; Blevins 1979 Table 8-1: 4.73004074). The shape is
// cosh + cos − σ(sinh + sin) with σ = (cosh β − cos β)/(sinh β − sin β), which is 2 at
// both ends; we halve it, so that φ = 1 at the ends and the mode's amplitude q is the ends'
// displacement. Then ∫₀ᴸ φ² ds = L/4 (the unhalved shape's is L: Blevins Table 8-1's
// normalisation), so a uniform beam's modal mass is m'L/4, and ∫ φ ds = ∫ (s − L/2) φ ds = 0:
// the mode is orthogonal to the rigid bounce and pitch of the uniform beam (tests check all
// three by quadrature).
#include "model/body_bending.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "shortest_text.hpp"

namespace railmodal::model {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// Newton on g(β) = cos β cosh β − 1 from the tabulated 4.73: the root to full precision
// (g' = cos β sinh β − sin β cosh β ≈ −112 there, far from zero; three steps converge).
double solve_beta1() {
  double beta = 4.73;
  for (int k = 0; k < 8; ++k) {
    const double g = std::cos(beta) * std::cosh(beta) - 1.0;
    const double slope = std::cos(beta) * std::sinh(beta) - std::sin(beta) * std::cosh(beta);
    beta -= g / slope;
  }
  return beta;
}

void require(bool ok, const Body& body, const std::string& rule) {
  if (!ok) throw std::invalid_argument("body '" + body.name + "': bending: " + rule);
}

bool positive_finite(double v) { return v > 0.0 && std::isfinite(v); }

}  // namespace

double free_free_beta1_l() {
  static const double beta = solve_beta1();
  return beta;
}

double free_free_mode_shape(double xi) {
  const double beta = free_free_beta1_l();
  const double sigma = (std::cosh(beta) - std::cos(beta)) / (std::sinh(beta) - std::sin(beta));
  const double b = beta * xi;
  return 0.5 * (std::cosh(b) + std::cos(b) - sigma * (std::sinh(b) + std::sin(b)));
}

double free_free_beam_frequency(double bending_stiffness, double mass_per_length, double length) {
  const double beta = free_free_beta1_l();
  return beta * beta / (kTwoPi * length * length) * std::sqrt(bending_stiffness / mass_per_length);
}

double BendingMode::shape_at(double x, const std::string& what) const {
  const double xi = (x - centre) / length + 0.5;
  // A point at an end, written in the file's few digits, may sit round-off beyond it.
  constexpr double kEndTolerance = 1e-9;
  if (!(xi >= -kEndTolerance && xi <= 1.0 + kEndTolerance))
    throw std::invalid_argument(what + " at x = " + shortest_text(x) + " m lies beyond the ends of the bending beam (x = " +
                                shortest_text(centre - 0.5 * length, 6) + " m to " + shortest_text(centre + 0.5 * length, 6) +
                                " m)");
  return free_free_mode_shape(xi);
}

BendingMode bending_mode(const Body& body) {
  if (!body.bending) throw std::invalid_argument("body '" + body.name + "' has no bending mode");
  const BodyBending& b = *body.bending;
  require(positive_finite(b.length), body, "the length must be positive and finite");
  require(!b.centre || std::isfinite(*b.centre), body, "the centre must be finite");
  require(b.beam.has_value() != b.mode.has_value(), body,
          "give exactly one of the beam (EI and mass per length) and the mode (frequency and modal mass)");
  require(b.damping_ratio >= 0.0 && b.damping_ratio < 1.0, body, "the damping ratio must be in [0, 1)");
  BendingMode m;
  m.length = b.length;
  m.centre = b.centre.value_or(body.centre_of_gravity.x());
  m.damping_ratio = b.damping_ratio;
  double frequency = 0.0;
  if (b.beam) {
    require(positive_finite(b.beam->bending_stiffness) && positive_finite(b.beam->mass_per_length), body,
            "EI and the mass per length must be positive and finite");
    frequency = free_free_beam_frequency(b.beam->bending_stiffness, b.beam->mass_per_length, b.length);
    m.modal_mass = 0.25 * b.beam->mass_per_length * b.length;  // ∫ m' φ² ds = m'L/4 (header)
  } else {
    require(positive_finite(b.mode->frequency) && positive_finite(b.mode->modal_mass), body,
            "the frequency and the modal mass must be positive and finite");
    frequency = b.mode->frequency;
    m.modal_mass = b.mode->modal_mass;
  }
  m.omega = kTwoPi * frequency;
  require(positive_finite(m.omega * m.omega * m.modal_mass), body, "the modal stiffness ω²·m_b overflows");
  return m;
}

}  // namespace railmodal::model
