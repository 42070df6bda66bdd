// A scene's simulation with only its named effects, and the FFT check of its result.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "railmodal/scene_simulation.hpp"

namespace railmodal {

namespace {

bool names(const Scene& scene, const char* effect) {
  return scene.simulation &&
         std::find(scene.simulation->effects.begin(), scene.simulation->effects.end(), effect) != scene.simulation->effects.end();
}

}  // namespace

NonlinearEffects scene_effects(const Scene& scene) {
  NonlinearEffects effects;
  effects.leaf_friction = names(scene, "leaf_friction");
  effects.progressive_springs = names(scene, "progressive_springs");
  effects.constant_friction = scene.simulation && scene.simulation->friction_law == "constant";
  return effects;
}

LinearSystem scene_system(const Scene& scene, const Vehicle& vehicle) {
  Vehicle v = vehicle;
  if (!names(scene, "viscous_dampers"))
    for (Element& e : v.elements) e.vertical_damping = e.lateral_damping = 0.0;  // not named: not built
  return assemble(v, scene.dofs);
}

TimeHistory simulate_scene(const Scene& scene, const Vehicle& vehicle) {
  if (!scene.simulation) throw std::invalid_argument("the scene has no [simulation] table");
  const SimulationSpec& spec = *scene.simulation;
  const LinearSystem system = scene_system(scene, vehicle);
  std::vector<const ExcitationSource*> sources;
  for (const auto& s : scene.sources) sources.push_back(s.get());
  SimulationOptions options;
  options.speed = spec.speed;
  options.final_speed = spec.final_speed;
  options.duration = spec.duration;
  options.time_step = spec.time_step;
  options.initial = spec.initial;
  options.tolerance = spec.tolerance;
  options.event_tolerance = spec.event_tolerance;
  const NonlinearEffects effects = scene_effects(scene);
  // A ramp changes the load's frequency as it goes: the adaptive path, which takes any forcing.
  return effects.any() || spec.final_speed > 0.0 ? simulate_nonlinear(system, sources, options, effects)
                                                 : simulate_linear(system, sources, options);
}

FftCheckResult fft_check(const Scene& scene, const Vehicle& vehicle) {
  FftCheckResult out;
  out.history = simulate_scene(scene, vehicle);
  const LinearSystem system = scene_system(scene, vehicle);
  out.modes = solve_modes(system);
  const double fs = 1.0 / scene.simulation->time_step;
  // Hann (the window for frequencies) with ×4 zero padding: interpolation error far below a bin.
  SpectrumOptions options;
  options.window = Window::hann;
  options.padding = Padding::to_length;
  const Eigen::Index n = out.history.time.size();
  options.padded_length = 4 * n;
  SpectrumAnalyzer analyzer(n, options);
  for (const Mode& mode : out.modes.modes) {
    if (mode.kind != ModeKind::oscillatory || mode.frequency_hz > fs / 4.0) continue;
    int dof = 0;
    for (int d = 1; d < mode.kinetic_energy_share.size(); ++d)
      if (mode.kinetic_energy_share(d) > mode.kinetic_energy_share(dof)) dof = d;
    const std::string label = system.dofs[dof].label;
    auto at = std::find(out.spectrum_dofs.begin(), out.spectrum_dofs.end(), label);
    if (at == out.spectrum_dofs.end()) {
      out.spectrum_dofs.push_back(label);
      out.spectra.push_back(analyzer.compute(out.history.displacement.col(dof), fs));
      at = out.spectrum_dofs.end() - 1;
    }
    const Spectrum& spectrum = out.spectra[at - out.spectrum_dofs.begin()];
    FftCheck check;
    check.mode = mode.index;
    check.mode_name = mode.name;
    check.dof = label;
    check.modal_hz = mode.frequency_hz;
    check.resolution_hz = spectrum.resolution;
    const SpectralPeak* nearest = nullptr;
    const auto peaks = find_peaks(spectrum);
    for (const auto& p : peaks)
      if (!nearest || std::abs(p.frequency - mode.frequency_hz) < std::abs(nearest->frequency - mode.frequency_hz))
        nearest = &p;
    if (nearest && std::abs(nearest->frequency - mode.frequency_hz) <= 3.0 * std::max(nearest->resolution, spectrum.resolution)) {
      check.peak_hz = nearest->frequency;
      check.resolution_hz = std::max(nearest->resolution, spectrum.resolution);
      check.rel_error = (nearest->frequency - mode.frequency_hz) / mode.frequency_hz;
      check.within_resolution = std::abs(nearest->frequency - mode.frequency_hz) <= check.resolution_hz;
    }
    out.checks.push_back(check);
  }
  if (scene_effects(scene).any()) {
    for (const Mode& mode : out.modes.modes) {
      if (mode.kind != ModeKind::oscillatory) continue;
      int dof = 0;
      for (int d = 1; d < mode.kinetic_energy_share.size(); ++d)
        if (mode.kinetic_energy_share(d) > mode.kinetic_energy_share(dof)) dof = d;
      out.swings = swings(out.history, dof);
      out.linear_half_period_s = 0.5 / mode.frequency_hz;
      break;
    }
  }
  return out;
}

}  // namespace railmodal
