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
    if (e.vertical_stages.size() != 1)
      throw std::invalid_argument("element '" + e.name + "': a " + (friction ? "leaf spring with friction" : "progressive spring") +
                                  " in series with other stages is not simulated yet (its massless end between the "
                                  "stages needs a play operator); give the element one vertical stage");
    if (system.element_vertical_map.row(static_cast<Eigen::Index>(k)).cwiseAbs().maxCoeff() == 0.0)
      continue;  // its vertical motion is not in this DOF set
    const SpringStage& stage = e.vertical_stages.front();
    NonlinearElement n;
    n.element = static_cast<int>(k);
    n.stretch = system.element_vertical_map.row(static_cast<Eigen::Index>(k));
    n.static_load = system.element_loads[k];
    n.tangent = series_stiffness(e.vertical_stages);
    n.friction = friction ? stage.relative_friction : 0.0;
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
