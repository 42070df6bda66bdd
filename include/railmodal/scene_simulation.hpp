// Running a scene in the time domain, and checking the spectrum of what it did against the
// modes.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/resort_car_free_response.toml");
//     railmodal::Vehicle vehicle = railmodal::load_vehicle(scene.vehicle_file);
//     railmodal::FftCheckResult r = railmodal::fft_check(scene, vehicle);
//     for (const railmodal::FftCheck& c : r.checks)
//       if (c.peak_hz)
//         std::cout << c.mode_name << ": modal " << c.modal_hz << " Hz, spectral peak " << *c.peak_hz << " Hz\n";
//   }
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

/// What the vehicle has, in the scene's DOF set, that the scene's [simulation] leaves out because
/// its effects do not name it (docs/scenes.md, "Only the named effects are built"), one sentence
/// a kind: "12 viscous dampers in the vehicle are not simulated: add effects =
/// [\"viscous_dampers\"]", and alike for leaf friction and progressive springs (simulated as
/// linear springs). Empty when the scene has no [simulation] or names every effect the vehicle
/// has. simulate and fft-check warn with it on stderr; the fft-check report writes it as notes.
std::vector<std::string> unsimulated_parts(const Scene& scene, const Vehicle& vehicle);

/// The nonlinearities the scene names (leaf_friction, progressive_springs).
NonlinearEffects scene_effects(const Scene& scene);

/// The memory, bytes, that a run may spend on the samples it must hold whole (an FFT needs the
/// whole record, and a JSON history is written a DOF at a time): 4 GB, fixed, so that a scene
/// is accepted or refused alike on every machine; half of a small 8 GB machine. Runs that
/// would need more are refused before a sample is computed, with the estimate
/// (docs/input.md, "Resource limits").
constexpr double kDefaultMemoryLimit = 4e9;

/// Runs the scene's [simulation] on the linear path, or on the nonlinear one when it names a
/// nonlinearity (std::invalid_argument if it has none).
TimeHistory simulate_scene(const Scene& scene, const Vehicle& vehicle);
/// The same, its samples given to each of `sinks` as they are produced (the history returned
/// holds no samples): memory stays bounded by what the sinks keep.
TimeHistory simulate_scene(const Scene& scene, const Vehicle& vehicle, const std::vector<HistorySink*>& sinks);

/// The columns of a scene's history that it outputs: the DOFs its [simulation] names, in the
/// history's order, or every DOF when it names none.
std::vector<int> output_columns(const TimeHistory& history, const Scene& scene);
std::vector<int> output_columns(const std::vector<std::string>& labels, const Scene& scene);

/// A sink that keeps the times and displacements of a scene's output columns, all that a JSON
/// history and the output spectra need: history() has the output DOFs as its labels and
/// columns, and no velocities. Its begin() refuses (std::invalid_argument, with the estimate)
/// a record over `memory_limit` bytes: 8 bytes a sample for the time and for each output, and
/// with `for_spectra` the spectra's own 16 a sample for each output and the transform's 120
/// (output_spectra: ×4 zero padding).
class OutputRecord final : public HistorySink {
 public:
  OutputRecord(const Scene& scene, bool for_spectra, double memory_limit = kDefaultMemoryLimit);
  void begin(const std::vector<std::string>& labels, Eigen::Index samples) override;
  void write(const Eigen::Ref<const Eigen::VectorXd>& time, const Eigen::Ref<const Eigen::MatrixXd>& displacement,
             const Eigen::Ref<const Eigen::MatrixXd>& velocity) override;
  /// The record, with the events, step count and summary of `result` (what simulate_scene
  /// returned); the record is moved out.
  TimeHistory history(TimeHistory result);

 private:
  const Scene& scene_;
  bool for_spectra_;
  double memory_limit_;
  std::vector<int> columns_;
  TimeHistory record_;
  Eigen::Index next_ = 0;
};

/// The amplitude spectra of a scene's outputs, taken as fft_check takes them (Hann window,
/// zero-padded ×4): peak amplitudes of the displacement in m or rad, up to the Nyquist
/// frequency. std::invalid_argument for a record of fewer than 2 samples.
struct OutputSpectra {
  std::vector<std::string> dofs;  ///< the output_columns' labels
  std::vector<Spectrum> spectra;  ///< one per DOF
};
OutputSpectra output_spectra(const TimeHistory& history, const Scene& scene);

/// One mode against the spectrum of the DOF where it dominates.
struct FftCheck {
  int mode = 0;
  std::string mode_name;
  /// The DOF the mode is checked on: where it dominates the record, the largest √M_dd·|φ_d|
  /// times the share of that DOF's motion the mode's coordinate can make (min(1,
  /// |φ_d|·max|η|/max|x_d|)), among the DOFs that move (√M_dd·max|x_d| above kExcitedRatio of
  /// the most moving one's): in a forced scene a DOF that the forcing drives through another
  /// mode is not where this one shows. A mode not excited: its most energetic DOF, and no
  /// spectrum is taken for it (resolution_hz is the record's fs/N).
  std::string dof;
  double modal_hz = 0.0;              ///< undamped natural frequency
  /// The frequency the peak is compared with: where the mode's free response oscillates,
  /// |Im λ|/2π of its damped mode (solve_damped_modes) when the scene builds damping (its named
  /// dampers, or the longitudinal ones that always stay), else modal_hz.
  double damped_hz = 0.0;
  double damping_ratio = 0.0;         ///< ζ of that damped mode (0 without damping)
  std::optional<double> peak_hz;      ///< the spectral peak nearest to it, if one is within 3 resolutions
  double rel_error = 0.0;             ///< (peak − damped)/damped
  double resolution_hz = 0.0;         ///< the peak's half-width at half amplitude (≥ the window's)
  bool within_resolution = false;     ///< |peak − damped| ≤ resolution
  /// How much the record holds of this mode: the largest |φᵀMx| over the record (the modal
  /// coordinate, one scale for every mode) over that of the most excited mode.
  double modal_amplitude_ratio = 0.0;
  /// Below kExcitedRatio the mode's "peak" would be round-off (a symmetric release leaves
  /// antisymmetric modes at 1e-13 of the rest): no peak is sought and the mode is reported
  /// as not excited.
  bool excited = false;
  static constexpr double kExcitedRatio = 1e-6;
  /// What |peak − modal| is held to, relative to modal_hz. A linear scene: its resolution
  /// (resolution_hz/modal_hz, the width of the line). A nonlinear scene: kNonlinearTolerance,
  /// checked only where the line is at least that narrow (resolution_hz ≤ kNonlinearTolerance·modal_hz).
  double tolerance = 0.0;
  /// What became of the check. Only `passed` and `failed` were checked: the others are neither
  /// a pass nor a failure. A linear scene's excited mode is always checked (no line there is a
  /// failure); a nonlinear scene's is not when the record cannot resolve the tolerance
  /// (`not_resolved`) or shows no line near the mode (`no_line`: friction holds it, or a
  /// forced nonlinear response); `not_applicable` where no record of this scene could check the
  /// mode by its line, whatever its length (`why_not_applicable` says why): a speed ramp (the
  /// response is not stationary), a constant-speed forcing whose own line lies within the
  /// tolerance of the mode (a peak there is the forcing's, whatever the mode) or within its
  /// resolution of the peak found with a linear forced response of at least a tenth of that
  /// peak's amplitude (the peak is the forcing's line), or a release that comes to rest (a
  /// longer run adds only rest). The forcing-line rules hold for linear scenes too (their
  /// forced response is exact). `decayed` (linear scenes): the mode's free response has died
  /// away where the Hann window weighs the record, so its line is not in the spectrum: the line
  /// it would make there, |φ_d|·A·g (A its free amplitude at t = 0 with the forced steady state
  /// taken out, g = the Hann gain of its decay e^{−σt} over the record), is under
  /// 1/kForcedLineShare of the spectrum's amplitude at its frequency (the forced response, other
  /// modes), and would not be without the decay (`why_decayed` says by how much and what to
  /// change). A peak read there would be another line's: not checked, never passed or failed.
  enum class Outcome { passed, failed, not_excited, not_resolved, no_line, not_applicable, decayed };
  Outcome outcome = Outcome::not_excited;
  bool checked() const { return outcome == Outcome::passed || outcome == Outcome::failed; }
  /// not_resolved: the record length that would resolve the tolerance, in s (the line's width
  /// falls as 1/duration: duration·resolution_hz/(kNonlinearTolerance·modal_hz)); else 0.
  double needed_duration_s = 0.0;
  /// not_applicable: why no run of this scene could check the mode, in words; else empty.
  std::string why_not_applicable;
  /// decayed: its decay, what is left of its line and what would check it, in words; else empty.
  std::string why_decayed;
  /// A line is another's (the forcing's, another mode's) when this mode could make less than
  /// 1/kForcedLineShare of the spectrum there; a forcing line takes the peak found when its
  /// linear forced response makes at least that share of it (scene_simulation.cpp says why ten).
  static constexpr double kForcedLineShare = 10.0;
  /// Friction and kinks are not expected to keep a line at the linear frequency: leaf friction
  /// R = φ·load moves the half periods to π/k₁, π/k₂ with k² = (1 ± φ)k₀² (springs digest
  /// (51), (63)), √(1 ± φ) − 1 ≤ 4.3 % for the book's φ ≤ 0.085; 5 % holds that and no more,
  /// and a line further away is not the mode's.
  static constexpr double kNonlinearTolerance = 0.05;
};
/// The words the fft-check reports write: "passed", "failed", "not excited", "not resolved",
/// "no line", "not applicable", "decayed".
const char* to_string(FftCheck::Outcome outcome);
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<FftCheck::Outcome> fft_check_outcome_from_string(const std::string& word);

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
  /// Nonlinear scenes: the swings of the most energetic DOF of the most excited mode, whose
  /// half periods check what broad spectral lines cannot.
  std::optional<Swings> swings;
  double linear_half_period_s = 0.0;  ///< π/ω of that mode, for comparison
  /// The check of a free friction decay by its half periods, made where its spectrum cannot
  /// check it: a release (no source) with leaf friction and no other effect that excites one
  /// mode only. Each half period between turning points must lie within `tolerance` of the
  /// mode's linear half period: leaf friction makes them π/k₁, π/k₂ with k² = (1 ± φ)k₀²
  /// (springs digest (51), (63)), up to 1/√(1 − φ) − 1 off (4.5 % at φ = 0.085); the tolerance
  /// is that for the vehicle's largest φ plus 1 %, at least FftCheck::kNonlinearTolerance.
  struct HalfPeriodCheck {
    int count = 0;                 ///< half periods between turning points compared
    double worst_rel_error = 0.0;  ///< the largest |half period − linear|/linear
    double tolerance = FftCheck::kNonlinearTolerance;
    bool passed = false;
  };
  std::optional<HalfPeriodCheck> half_period_check;
  bool nonlinear = false;             ///< the scene names a nonlinearity: checks held to kNonlinearTolerance
  int checked = 0;                    ///< checks that were made (FftCheck::checked(), and half_period_check)
  int failed = 0;                     ///< of those, outside their tolerance: the verdict FAILED (exit 6)
  /// The verdict: at least one check made and none failed. Not passed and not failed when
  /// nothing could be checked (checked == 0): "not checked" is not a pass (the command exits 6
  /// for it as for a failure: the check asked for was not made; the verdict says which).
  bool passed = false;
  /// The checks (modes checked, excited, within resolution) and the stage times; the
  /// simulation, modes and spectra carry their own.
  AnalysisSummary summary;
};

/// Simulates the scene and compares the spectral peaks of each excited oscillatory mode's
/// most energetic DOF with the modal frequencies (modes above half the Nyquist frequency are
/// left out: the step cannot resolve them), each within its FftCheck::tolerance where the record
/// can check it (FftCheck::outcome); `failed` counts those outside, `checked` those made. A failed check is an answer,
/// not an exception. It holds the whole record of every DOF, with velocities, and spectra: refused before simulating
/// (std::invalid_argument, with the estimate) when that would take over `memory_limit` bytes, estimated as 40 bytes a
/// sample for each DOF and 100 for the transform (measured: 294 bytes a sample for 6 DOFs).
FftCheckResult fft_check(const Scene& scene, const Vehicle& vehicle, double memory_limit = kDefaultMemoryLimit);

}  // namespace railmodal
