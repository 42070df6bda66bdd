#include "simulate/nonlinear_elements.hpp"

#include <cmath>
#include <stdexcept>

namespace railmodal::simulate {

constexpr double kTwoPi = 6.28318530717958647692;

void NonlinearElement::track_motion(double t, double* u, double* du, double* ddu) const {
  *u = *du = *ddu = 0.0;
  for (const TrackHarmonic& h : track) {
    const std::complex<double> e = h.amplitude * std::exp(std::complex<double>(0.0, h.omega * (t - h.delay)));
    *u += e.real();
    *du += (std::complex<double>(0.0, h.omega) * e).real();
    *ddu -= h.omega * h.omega * e.real();
  }
}

std::vector<NonlinearElement> nonlinear_elements(const LinearSystem& system, const std::vector<HarmonicLoad>& loads,
                                                 const NonlinearEffects& effects) {
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
    if (e.lower.empty())
      for (const HarmonicLoad& load : loads)
        for (const WheelInput& w : load.wheels)
          if (system.track_inputs[w.track_input].element == n.element && w.amplitude(2) != 0.0)
            n.track.push_back({w.amplitude(2), kTwoPi * load.frequency_hz, w.delay_s});
    out.push_back(std::move(n));
  }
  return out;
}

}  // namespace railmodal::simulate
