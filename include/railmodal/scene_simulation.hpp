// Running a scene in the time domain, and checking the spectrum of what it did against the
// modes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "railmodal/modal.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/simulation.hpp"
#include "railmodal/spectrum.hpp"

namespace railmodal {

/// The system a scene simulates: the vehicle assembled in the scene's DOF set with only the
/// effects it names — without "viscous_dampers" the dampers are not built (C = 0 and no
/// velocity input at the wheels).
LinearSystem scene_system(const Scene& scene, const Vehicle& vehicle);

/// The nonlinearities the scene names (leaf_friction, progressive_springs).
NonlinearEffects scene_effects(const Scene& scene);

/// Runs the scene's [simulation] on the linear path, or on the nonlinear one when it names a
/// nonlinearity (std::invalid_argument if it has none).
TimeHistory simulate_scene(const Scene& scene, const Vehicle& vehicle);

/// One mode against the spectrum of its most energetic DOF.
struct FftCheck {
  int mode = 0;
  std::string mode_name;
  std::string dof;
  double modal_hz = 0.0;              ///< undamped natural frequency
  std::optional<double> peak_hz;      ///< the spectral peak nearest to it, if one is within 3 resolutions
  double rel_error = 0.0;             ///< (peak − modal)/modal
  double resolution_hz = 0.0;         ///< the peak's half-width at half amplitude (≥ the window's)
  bool within_resolution = false;     ///< |peak − modal| ≤ resolution
};

/// Where one degree of freedom turns and where it passes its static position, read from a
/// sampled history by cubic Hermite interpolation of displacement and velocity (error O(Δt⁴)).
/// Friction decay is a chain of cosine arcs about shifted centres, so its half periods show
/// between turning points (π/k₁, π/k₂: springs digest (51), (63)); a spring with a kink at the
/// static position shows its two half periods between crossings (Example 10).
struct Swings {
  std::string dof;
  std::vector<double> turning_times;     ///< s
  std::vector<double> turning_values;    ///< displacement there (m or rad)
  std::vector<double> crossing_times;    ///< s, passes through 0
  bool comes_to_rest = false;            ///< the last samples do not move (a stuck spring)
  std::vector<double> half_periods_between_turns() const;
  std::vector<double> half_periods_between_crossings() const;
};
Swings swings(const TimeHistory& history, int dof);

struct FftCheckResult {
  TimeHistory history;
  ModalResult modes;
  std::vector<FftCheck> checks;
  std::vector<std::string> spectrum_dofs;  ///< the DOFs whose spectra were taken
  std::vector<Spectrum> spectra;           ///< of their displacements, Hann window, zero-padded ×4
  /// Nonlinear scenes: the swings of the most energetic DOF of the lowest mode, whose
  /// half periods check what broad spectral lines cannot.
  std::optional<Swings> swings;
  double linear_half_period_s = 0.0;  ///< π/ω of that mode, for comparison
};

/// Simulates the scene and compares the spectral peaks of each oscillatory mode's most
/// energetic DOF with the modal frequencies (modes above half the Nyquist frequency are left
/// out: the step cannot resolve them).
FftCheckResult fft_check(const Scene& scene, const Vehicle& vehicle);

}  // namespace railmodal
