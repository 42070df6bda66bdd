#include "simulate/nonlinear_elements.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railmodal::simulate {

constexpr double kTwoPi = 6.28318530717958647692;

void NonlinearElement::track_motion(double t, double* u, double* du, double* ddu) const {
  *u = *du = *ddu = 0.0;
  const double V = profile.speed(t), x = profile.distance(t), a = profile.acceleration;
  for (const TrackHarmonic& h : track) {
    const std::complex<double> e = h.amplitude * std::exp(std::complex<double>(0.0, h.wavenumber * x - h.lag));
    const double w = h.wavenumber * V;  // the harmonic's circular frequency now
    if (a == 0.0 || !h.source) {  // r = 1: a fixed profile, or a constant speed
      *u += e.real();
      *du += (std::complex<double>(0.0, w) * e).real();
      *ddu += (std::complex<double>(0.0, h.wavenumber * a) * e).real() - w * w * e.real();
      continue;
    }
    // u = Re(e·r(ω)), ω̇ = κa: u̇ = Re(e(ṙ + irω)), ü = Re(e(r̈ + 2iṙω + irκa − rω²)), with
    // the derivatives of r(ω) by central differences (r is smooth away from a track resonance).
    const double dw = 1e-4 * std::max(std::abs(w), 1e-3 * std::abs(h.omega));
    const double r = h.source->load_scale(w, h.omega);
    const double rp = h.source->load_scale(w + dw, h.omega), rm = h.source->load_scale(w - dw, h.omega);
    const double wd = h.wavenumber * a;
    const double r1 = (rp - rm) / (2 * dw) * wd, r2 = (rp - 2 * r + rm) / (dw * dw) * wd * wd;
    const std::complex<double> i(0.0, 1.0);
    *u += (e * r).real();
    *du += (e * (r1 + i * r * w)).real();
    *ddu += (e * (r2 + 2.0 * i * r1 * w + i * r * wd - r * w * w)).real();
  }
}

// A leaf spring with friction in series with elastic stages (springs digest §2.5, eqs.
// (70)–(86); bogie-wagons-natural digest §2.1, eqs. (192)–(193)) is one element with one
// internal state, the leaf's own dynamic deflection s; the joint between the leaf and the
// coils has no mass, so it is not a degree of freedom.
//
// Let δ be the dynamic compression of the pair from equilibrium, P₀ its static load, c_l the
// leaf's stiffness and k_c the series stiffness of the elastic stages (1/k_c = Σ 1/(n·c)).
// Stages in series carry one force, the coils' F = P₀ + k_c(δ − s). The leaf's elastic reaction
// is R = P₀ + c_l·s, i.e. the book's c(f + z) with the static deflection f = P₀/c_l carrying
// the preload, and its friction is φR (the law R(1 ± φ), eqs. (40), (58)): the leaf holds
// (ṡ = 0) while F lies in its friction band
//     (1 − φ)R ≤ F ≤ (1 + φ)R,
// and slides on an edge of it otherwise: F = (1 + σφ)R with σ = +1 into compression, −1 out.
// Sliding, s follows from δ alone: P₀ + k_c(δ − s) = (1 + σφ)(P₀ + c_l·s) gives
//     s = (k_c·δ − σφP₀) / (k_c + (1 + σφ)c_l),
// the book's (192e) z₁ = (2c₂z₂ ∓ φ₁c₁f₁)/(2c₂ + (1 ± φ₁)c₁) per leaf end (with the sign of the
// φ₁c₁f₁ term as the digest re-derives it, §2.5). Since ṡ = k_c·δ̇/(k_c + (1 + σφ)c_l) has the sign
// of δ̇, a slide ends when δ̇ reaches 0: the leaf then holds its s, and the pair is the coils
// alone until F, moving at k_c·δ̇, reaches the other edge (stick → slip, slip in the direction of
// the edge reached). Both are events of the integrator; s is carried across them continuously
// (at a stick→slip event F is on the edge, where the sliding s equals the held one).
// Unloading: a leaf in tension (R < 0) carries no friction (the law is φ·R of the load the
// leaf carries), its band closes, and it follows the frictionless split s = k_c·δ/(k_c + c_l);
// it cannot stick until it carries load again. Under the constant law the band is ±φP₀.
double NonlinearElement::sliding_leaf_deflection(double delta, int direction) const {
  const double stiffening = constant_friction ? 0.0 : direction * friction;  // σφ of (1 + σφ)c_l
  const double s = (coil_stiffness * delta - direction * friction * static_load) /
                   (coil_stiffness + (1.0 + stiffening) * leaf_stiffness);
  if (direction == 0 || constant_friction || leaf_reaction(s) >= 0.0) return s;
  return coil_stiffness * delta / (coil_stiffness + leaf_stiffness);
}

namespace {

// What an element's vertical stages make of it: the one friction stage (-1: none) and the
// series stiffness of the others. Throws for what the simulation does not model.
struct SeriesStages {
  int friction = -1;
  double others = 0.0;  ///< N/m; 0 with no other stage
};

SeriesStages series_stages(const Element& e, bool friction, bool progressive) {
  SeriesStages out;
  std::vector<SpringStage> others;
  for (size_t s = 0; s < e.vertical_stages.size(); ++s) {
    const SpringStage& stage = e.vertical_stages[s];
    if (friction && stage.relative_friction > 0.0) {
      if (out.friction >= 0)
        throw std::invalid_argument("element '" + e.name +
                                    "': two leaf springs with friction in series are not simulated; give it one");
      out.friction = static_cast<int>(s);
    } else {
      others.push_back(stage);
    }
  }
  if (progressive && e.vertical_stages.size() != 1)
    throw std::invalid_argument("element '" + e.name +
                                "': a progressive spring in series with other stages is not simulated (its curve "
                                "would split the force between the stages); give the element one vertical stage");
  if (out.friction >= 0) out.others = series_stiffness(others);
  return out;
}

}  // namespace

std::vector<NonlinearElement> nonlinear_elements(const LinearSystem& system, const std::vector<HarmonicLoad>& loads,
                                                 const NonlinearEffects& effects,
                                                 const std::vector<const ExcitationSource*>& load_sources,
                                                 const SpeedProfile& profile) {
  std::vector<NonlinearElement> out;
  const auto& elements = system.vehicle.elements;
  for (size_t k = 0; k < elements.size(); ++k) {
    const Element& e = elements[k];
    bool friction = false, progressive = false;
    for (const SpringStage& s : e.vertical_stages) {
      friction = friction || (effects.leaf_friction && s.relative_friction > 0.0);
      progressive = progressive || (effects.progressive_springs && s.curve);
    }
    if (!friction && !progressive) continue;
    const SeriesStages stages = series_stages(e, friction, progressive);
    if (system.element_vertical_map.row(static_cast<Eigen::Index>(k)).cwiseAbs().maxCoeff() == 0.0)
      continue;  // its vertical motion is not in this DOF set
    const SpringStage& stage = e.vertical_stages[std::max(stages.friction, 0)];
    NonlinearElement n;
    n.element = static_cast<int>(k);
    n.stretch = system.element_vertical_map.row(static_cast<Eigen::Index>(k));
    n.static_load = system.element_loads[k];
    n.tangent = series_stiffness(e.vertical_stages);
    n.friction = friction ? stage.relative_friction : 0.0;
    n.constant_friction = effects.constant_friction;
    n.leaf_stiffness = stage.stiffness * stage.count;
    n.coil_stiffness = stages.others;
    if (progressive) {
      n.curve = stage.curve;
      n.springs = stage.count;
      if (!(n.static_load > 0.0))
        throw std::invalid_argument("element '" + e.name + "': a progressive spring must carry a static load");
      n.static_deflection = n.curve->deflection_at(n.static_load / n.springs);
    }
    n.profile = profile;
    if (e.lower.empty())
      for (size_t l = 0; l < loads.size(); ++l)
        for (const WheelInput& w : loads[l].wheels)
          if (system.track_inputs[w.track_input].element == n.element && w.amplitude(2) != 0.0) {
            const double omega = kTwoPi * loads[l].frequency_hz;
            // κ = ω/V; at rest (no speed: a free response has no sources) nothing moves.
            const double wavenumber = profile.initial > 0.0 ? omega / profile.initial : 0.0;
            n.track.push_back({w.amplitude(2), omega, omega * w.delay_s, wavenumber,
                               l < load_sources.size() ? load_sources[l] : nullptr});
          }
    out.push_back(std::move(n));
  }
  return out;
}

}  // namespace railmodal::simulate
