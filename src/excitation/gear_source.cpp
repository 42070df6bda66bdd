// The driving gear as an excitation source (issue 22 item 4; docs/driving_gear.md, "As an
// excitation"): the harmonics of the exact rod forces (src/gear/) placed on the vehicle's bodies.
// Every force of the gear is an inertia force at steady rotation, so it is ω² times a function of
// the crank angle alone: the harmonics are taken once, at a reference speed, and scaled by
// (V/V_ref)² (load_scales, as the simple form's m ρ ω²).
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/point_motion.hpp"
#include "railmodal/driving_gear.hpp"
#include "railmodal/excitation.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;
const std::complex<double> kI(0.0, 1.0);
// Any speed serves: only the harmonics' ratio to ω² is kept. 10 m/s keeps the forces of order
// 10³–10⁴ N, far from overflow and underflow.
constexpr double kReferenceSpeed = 10.0;

// Where one force of the gear acts and how it varies with the reference crank angle φ:
// q(φ) = Σ_k a_k cos kφ + b_k sin kφ, per unit ω² (N·s²).
struct GearForce {
  bool axle_body = false;  ///< on the axle's body (its vertical forces), else on the frame
  int axle = 0;
  int direction = 0;       ///< 0 longitudinal, 2 vertical (PointForce::amplitude's index)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::vector<GearHarmonic> harmonics;  ///< orders 0 … highest
};

// The harmonics of c·ω² at reference speed, per unit ω².
std::vector<GearHarmonic> per_omega2(std::vector<GearHarmonic> h, double omega2) {
  for (auto& k : h) k.cosine /= omega2, k.sine /= omega2;
  return h;
}

// A mass m at radius ρ turning at θ = φ + δ pulls with (−cos θ, sin θ)·m ω² ρ (x forward,
// y up; docs/driving_gear.md): first harmonics only.
std::vector<GearHarmonic> mass_harmonics(double m_rho, double delta, bool vertical, int highest) {
  std::vector<GearHarmonic> h(highest + 1);
  for (int k = 0; k <= highest; ++k) h[k].order = k;
  if (vertical) h[1].cosine = m_rho * std::sin(delta), h[1].sine = m_rho * std::cos(delta);
  else h[1].cosine = -m_rho * std::cos(delta), h[1].sine = m_rho * std::sin(delta);
  return h;
}

class GearSource final : public ExcitationSource {
 public:
  explicit GearSource(const GearExcitation& p) : p_(p) {
    std::string why;
    if (!p.gear.is_valid(&why)) throw std::invalid_argument("driving_gear: " + why);
    if (p.harmonics < 1 || p.harmonics > 60) throw std::invalid_argument("driving_gear: harmonics must lie in 1 … 60");
    if (!p.axles.empty() && p.axles.size() != p.gear.axles.size())
      throw std::invalid_argument("driving_gear: " + std::to_string(p.axles.size()) + " axle places for " +
                                  std::to_string(p.gear.axles.size()) + " axles");
    if (!std::isfinite(p.crank_angle)) throw std::invalid_argument("driving_gear: crank_angle must be finite");
    for (const auto& a : p_.axles)
      if (!std::isfinite(a.x)) throw std::invalid_argument("driving_gear: an axle's x must be finite");
    build_forces();
  }
  std::string kind() const override { return "driving_gear"; }
  std::string description() const override {
    std::ostringstream out;
    out << "driving gear" << (p_.gear.name.empty() ? "" : " '" + p_.gear.name + "'") << " on '" << p_.body
        << "', D = " << p_.gear.wheel_diameter << " m, " << p_.gear.cylinders.size() << " cylinders, "
        << p_.gear.axles.size() << " axles (exact rod forces, ∝ V²)";
    return out.str();
  }
  double wavelength() const override { return kPi * p_.gear.wheel_diameter; }
  int harmonic_count() const override { return p_.harmonics; }
  void load_scales(const double* omega, int count, double reference_omega, double* out) const override {
    for (int i = 0; i < count; ++i) out[i] = (omega[i] / reference_omega) * (omega[i] / reference_omega);
  }
  std::optional<Misfit> misfit(const LinearSystem& system) const override {
    if (model::body_index(system, p_.body) < 0) return Misfit{"body", "the vehicle has no body '" + p_.body + "'"};
    for (const auto& a : p_.axles)
      if (!a.body.empty() && model::body_index(system, a.body) < 0)
        return Misfit{"axle", "the vehicle has no body '" + a.body + "'"};
    return std::nullopt;
  }

  HarmonicLoad load_at(const LinearSystem& system, double speed, int harmonic) const override {
    if (const auto m = misfit(system)) throw std::invalid_argument("driving_gear: " + m->reason);
    HarmonicLoad out;
    out.frequency_hz = frequency_hz(speed, harmonic);
    const double omega = 2.0 * speed / p_.gear.wheel_diameter;
    const int frame = model::body_index(system, p_.body);
    for (const GearForce& f : forces_) {
      const GearHarmonic& h = f.harmonics[harmonic];
      if (h.cosine == 0.0 && h.sine == 0.0) continue;
      PointForce pf;
      pf.body = frame;
      if (f.axle_body && !p_.axles.empty() && !p_.axles[f.axle].body.empty())
        pf.body = model::body_index(system, p_.axles[f.axle].body);
      pf.point = f.point;
      pf.amplitude(f.direction) = omega * omega * phasor(h, harmonic);
      out.forces.push_back(pf);
    }
    return out;
  }

 private:
  // a cos kφ + b sin kφ with φ = φ₀ ± ωt is Re(A e^{ikωt}): A = (a − ib)e^{ikφ₀} running
  // forward, its conjugate (a + ib)e^{−ikφ₀} backward.
  std::complex<double> phasor(const GearHarmonic& h, int k) const {
    const std::complex<double> forward = std::complex<double>(h.cosine, -h.sine) * std::exp(kI * (k * p_.crank_angle));
    return p_.gear.rotation == GearRotation::forward ? forward : std::conj(forward);
  }

  double axle_x(int axle) const {
    return p_.axles.empty() ? p_.gear.axles[axle].position : p_.axles[axle].x;
  }

  void add(bool axle_body, int axle, int direction, double x, double lateral, std::vector<GearHarmonic> h) {
    GearForce f;
    f.axle_body = axle_body;
    f.axle = axle;
    f.direction = direction;
    f.point = {x, -lateral, 0.0};  // the gear's lateral is + right, the vehicle's y + left
    f.harmonics = std::move(h);
    forces_.push_back(std::move(f));
  }

  void build_forces() {
    GearOptions options;
    options.harmonics = p_.harmonics;
    const GearResult r = solve_driving_gear(p_.gear, kReferenceSpeed, options);
    const double omega2 = r.omega * r.omega;
    for (size_t c = 0; c < p_.gear.cylinders.size(); ++c) {
      const GearCylinder& cyl = p_.gear.cylinders[c];
      const double x = axle_x(cyl.axle);
      // X and Y at the crank pin, taken at the axle centre: their moments about it turn the
      // wheel (its spin), which no body's degree of freedom holds.
      add(false, cyl.axle, 0, x, cyl.lateral, per_omega2(r.horizontal_harmonics[c], omega2));
      add(true, cyl.axle, 2, x, cyl.lateral, per_omega2(r.vertical_harmonics[c], omega2));
      // Z at the middle of the crosshead's stroke, x_B = L (the stroke runs from L − r to L + r);
      // the moment Z·(x_B − L) of its motion along the bars, a product of two oscillations, is
      // left out. Z's weight term is its order 0, which no harmonic k ≥ 1 carries.
      add(false, cyl.axle, 2, x + cyl.rod_length, cyl.lateral, per_omega2(r.guide_harmonics[c], omega2));
    }
    const double S = p_.gear.wheel_plane_half_spacing;
    for (size_t a = 0; a < p_.gear.axles.size(); ++a) {
      const GearAxle& axle = p_.gear.axles[a];
      for (const bool right : {true, false}) {
        const GearWheel& wheel = right ? axle.right : axle.left;
        for (const RotatingMass& m : wheel.masses) {
          const double lateral = (right ? 1.0 : -1.0) * (S + m.plane_offset);
          const double delta = wheel.crank_offset + m.angle;
          const double m_rho = m.mass * m.radius;
          add(false, static_cast<int>(a), 0, axle_x(static_cast<int>(a)), lateral,
              mass_harmonics(m_rho, delta, false, p_.harmonics));
          add(true, static_cast<int>(a), 2, axle_x(static_cast<int>(a)), lateral,
              mass_harmonics(m_rho, delta, true, p_.harmonics));
        }
      }
    }
  }

  GearExcitation p_;
  std::vector<GearForce> forces_;
};

}  // namespace

std::unique_ptr<ExcitationSource> make_source(const GearExcitation& excitation) {
  return std::make_unique<GearSource>(excitation);
}

}  // namespace railmodal
