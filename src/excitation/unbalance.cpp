// Unbalanced running gear: rotating unbalance and the reciprocating masses of cranks
// (unbalance-excitation digest §2.2, §2.6 and §3). Forces grow with ω² = (2V/D)².
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "railmodal/excitation.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;
const std::complex<double> kI(0.0, 1.0);

class UnbalanceSource final : public ExcitationSource {
 public:
  explicit UnbalanceSource(const Unbalance& p) : p_(p) {
    if (!(p.wheel_diameter > 0.0)) throw std::invalid_argument("unbalance: wheel_diameter must be positive");
    if (p.rotating.empty() && p.reciprocating.empty())
      throw std::invalid_argument("unbalance: give at least one rotating or reciprocating mass");
    if (p.harmonics < 1) throw std::invalid_argument("unbalance: at least one harmonic");
    for (const auto& r : p.reciprocating)
      if (!(r.rod_ratio >= 0.0 && r.rod_ratio < 1.0))
        throw std::invalid_argument("unbalance: the rod ratio r/L must lie in [0, 1)");
  }
  std::string kind() const override { return "unbalance"; }
  std::string description() const override {
    std::ostringstream out;
    out << "unbalance on '" << p_.body << "', D = " << p_.wheel_diameter << " m, " << p_.rotating.size()
        << " rotating and " << p_.reciprocating.size() << " reciprocating masses (force ∝ V²)";
    return out.str();
  }
  double wavelength() const override { return kPi * p_.wheel_diameter; }
  void load_scales(const double* omega, int count, double reference_omega, double* out) const override {
    for (int i = 0; i < count; ++i) out[i] = (omega[i] / reference_omega) * (omega[i] / reference_omega);  // m ρ ω²
  }
  int harmonic_count() const override { return p_.harmonics; }
  std::optional<Misfit> misfit(const LinearSystem& system) const override {
    if (body_index(system) < 0) return Misfit{"body", "the vehicle has no body '" + p_.body + "'"};
    return std::nullopt;
  }

  HarmonicLoad load_at(const LinearSystem& system, double speed, int harmonic) const override {
    HarmonicLoad out;
    out.frequency_hz = frequency_hz(speed, harmonic);
    if (const auto m = misfit(system)) throw std::invalid_argument("unbalance: " + m->reason);
    const int body = body_index(system);
    const double omega = 2.0 * speed / p_.wheel_diameter;  // wheel turning speed, rad/s
    const double omega2 = omega * omega;
    if (harmonic == 1)
      for (const auto& r : p_.rotating) {
        // Vertical m ρ ω² sin(ωt + φ), longitudinal m ρ ω² cos(ωt + φ).
        PointForce f;
        f.body = body;
        f.point = {r.x, r.y, r.z};
        const std::complex<double> turn = std::exp(kI * r.phase) * (r.mass_radius * omega2);
        f.amplitude = Eigen::Vector3cd(turn, 0.0, -kI * turn);
        out.forces.push_back(f);
      }
    for (const auto& r : p_.reciprocating) {
      // X = m r ω² Σ Aₙ cos n(ωt + φ): order n is this harmonic.
      const double A = reciprocating_coefficient(r.rod_ratio, harmonic);
      if (A == 0.0) continue;
      PointForce f;
      f.body = body;
      f.point = {r.x, r.y, r.z};
      f.amplitude(0) = r.mass * r.crank_radius * omega2 * A * std::exp(kI * (harmonic * r.phase));
      out.forces.push_back(f);
    }
    return out;
  }

 private:
  int body_index(const LinearSystem& system) const {
    const auto& bodies = system.vehicle.bodies;
    for (size_t b = 0; b < bodies.size(); ++b)
      if (bodies[b].name == p_.body) return static_cast<int>(b);
    return -1;
  }

  Unbalance p_;
};

}  // namespace

double reciprocating_coefficient(double rod_ratio, int order) {
  if (!(rod_ratio >= 0.0 && rod_ratio < 1.0)) throw std::invalid_argument("rod ratio r/L must lie in [0, 1)");
  if (order < 1) throw std::invalid_argument("order must be at least 1");
  if (order == 1) return 1.0;
  // The piston stands at x = r cos θ + L√(1 − λ² sin²θ); at steady ω its acceleration is
  // −ω² r Σ Aₙ cos nθ with Aₙ = n² sₙ/λ, sₙ the cosine coefficients of √(1 − λ² sin²θ).
  // The trapezoidal rule is exact to round-off for this smooth periodic function (its
  // coefficients fall like λ^n); Kvasnikov's truncated series (A₂ = λ + λ³/4 + 15λ⁵/128,
  // A₄ = −(λ³/4 + 3λ⁵/16), …) differ from it by up to 1e-5 at λ = 1/4 (digest E13).
  if (rod_ratio == 0.0 || order % 2 == 1) return 0.0;  // √(1 − λ² sin²θ) has only even orders
  constexpr int kPoints = 256;
  double s_n = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const double theta = 2.0 * kPi * i / kPoints;
    const double sine = std::sin(theta);
    s_n += std::sqrt(1.0 - rod_ratio * rod_ratio * sine * sine) * std::cos(order * theta);
  }
  s_n *= 2.0 / kPoints;
  return order * order * s_n / rod_ratio;
}

std::unique_ptr<ExcitationSource> make_source(const Unbalance& unbalance) {
  return std::make_unique<UnbalanceSource>(unbalance);
}

}  // namespace railmodal
