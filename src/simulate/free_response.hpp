// The free part of a linear scene's response, mode by mode: what is left once the steady state
// that the periodic sources force is taken out, how fast it decays, and how much of it a Hann
// spectrum of the whole record can still show. fft-check asks it whether a damped mode's own
// line is in the record at all before it reads a peak as that mode's.
#pragma once

#include <vector>

#include "railmodal/damped_modal.hpp"
#include "railmodal/excitation.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/simulation.hpp"

namespace railmodal::simulate {

/// One undamped mode's free motion in a linear scene.
struct FreeMode {
  /// |Im λ|/2π of the damped mode it belongs to, Hz: where its free response oscillates
  /// (the undamped frequency when the scene builds no damping).
  double damped_hz = 0.0;
  double damping_ratio = 0.0;  ///< ζ (0 without damping)
  double decay_rate = 0.0;     ///< σ = −Re λ, 1/s: the free response falls as e^{−σt}
  /// The free response's amplitude at t = 0 in the mass-normalised modal coordinate
  /// (m·√kg): √(η₀² + ((η̇₀ + ση₀)/ω_d)²) of η₀ = φᵀM(x₀ − x_ss(0)), η̇₀ = φᵀM(v₀ − v_ss(0)).
  double initial_amplitude = 0.0;
};

/// For each mode of `modes` (0 for the modes that do not oscillate): its damped frequency and
/// decay (from `damped`, matched by DampedMode::undamped_mode; none: undamped) and its free
/// amplitude at t = 0 for the start `initial`, the steady state of `sources` at `speed`
/// (x_ss(t) = Σ Re(X_n e^{iω_n t}), X_n of (K − ω²M + iωC)X_n = Q_n, the load the linear
/// simulation integrates) taken out. Modal coordinates of undamped shapes: exact for
/// proportional damping, a first-order estimate otherwise.
std::vector<FreeMode> free_modes(const LinearSystem& system, const ModalResult& modes, const DampedModalResult* damped,
                                 const std::vector<const ExcitationSource*>& sources, double speed,
                                 const std::vector<InitialCondition>& initial);

/// The amplitude a Hann-windowed spectrum of a record of `duration` s reads at its own frequency
/// for a tone decaying as e^{−σt} from t = 0, over what it reads for the same tone held steady:
/// ∫₀ᵀ w e^{−σt} dt / ∫₀ᵀ w dt with w = ½(1 − cos 2πt/T), which is
/// (1 − e^{−σT})/(σT) · Ω²/(σ² + Ω²), Ω = 2π/T. 1 at σ = 0; 4π²/(σT)³ for σT ≫ 1 (the window
/// is near zero where the tone still is).
double hann_decay_gain(double decay_rate, double duration);

}  // namespace railmodal::simulate
