// Steady harmonic response and critical speeds.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/two_axle_freight_wagon.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::vertical);
//     auto modes = railmodal::solve_modes(system);
//     railmodal::RailJoints joints;
//     joints.rail_length = 12.5;
//     joints.dip_depth = 0.005;
//     auto source = railmodal::make_source(joints);
//     railmodal::CriticalSpeedOptions options;
//     options.min_speed = 10.0 / 3.6;
//     options.max_speed = 120.0 / 3.6;
//     for (const railmodal::CriticalSpeed& c : railmodal::find_critical_speeds(system, modes, {source.get()}, options))
//       std::cout << c.speed * 3.6 << " km/h: harmonic " << c.harmonic << " meets " << c.mode_name << "\n";
//     // the amplitude of body bounce from 10 to 120 km/h
//     std::vector<double> speeds;
//     for (double v = 10.0; v <= 120.0; v += 1.0) speeds.push_back(v / 3.6);
//     railmodal::OutputRequest bounce;
//     bounce.dof = system.index_of("body.bounce");
//     auto curves = railmodal::amplitude_curves(system, modes, *source, 0, {bounce}, speeds);
//     std::cout << curves.front().amplitudes.size() << " speeds\n";
//   }
//
// The steady state of M ẍ + C ẋ + K x = Re(Q e^{iωt}) is x = Re(X e^{iωt}) with
// (K − ω²M + iωC) X = Q. Displacement input at the wheels makes X/u a displacement
// transmissibility; a force input makes X/F a receptance (iωX/F mobility, −ω²X/F
// accelerance). Without damping, a loaded mode at ω has no steady state: the amplitude
// grows linearly in time (the book's secular forms (168d), (274)), and that is reported as
// unbounded with its growth per half period, never as inf or NaN.
#pragma once

#include <Eigen/Core>
#include <complex>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/excitation.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/summary.hpp"

namespace railmodal {

struct HarmonicResponse {
  double frequency_hz = 0.0;
  /// Complex amplitude per DOF (m, rad). When unbounded: the finite rest of the response,
  /// without the resonant modes (exact where they do not move a DOF).
  Eigen::VectorXcd displacement;
  bool unbounded = false;            ///< an undamped mode the load drives sits at this frequency
  int resonant_mode = 0;             ///< the first such mode (1-based) when unbounded
  std::vector<int> resonant_modes;   ///< all of them (repeated frequencies give several)
};

/// Whether the response at this DOF is unbounded: a resonant mode of `response` moves it
/// (an entry above 1e-9 of the mode's largest).
bool unbounded_at(const HarmonicResponse& response, const ModalResult& modes, int dof);

/// Direct solve of (K − ω²M + iωC) X = Q (dense LU). `modes` (of the same system) is used
/// to recognise undamped modes at ω: they are exact null vectors of the dynamic stiffness,
/// so the rest of the response is solved with them bordered out, and the response is
/// unbounded where a driven one moves a DOF. A mode is driven when its modal force |φᵀQ|
/// exceeds 1e-9·‖φ‖·`source_load_norm`, the norm of the whole source's load √(Σ_k ‖Q_k‖²)
/// over its harmonics when `load` is one of them (0, or less than ‖Q‖: the load's own norm):
/// a harmonic that is itself round-off of its source (the 3rd harmonic of a cosine dip as long
/// as the rail) drives nothing. The critical speeds and curves pass their source's.
HarmonicResponse harmonic_response(const LinearSystem& system, const ModalResult& modes, const Eigen::VectorXcd& load,
                                   double frequency_hz, double source_load_norm = 0.0);

/// Modal superposition over the lowest `mode_count` modes (all if ≤ 0) with modal damping
/// taken from the diagonal of ΦᵀCΦ (exact when C = 0 or C is proportional and no damper
/// acts on a massless DOF), plus the response of massless (condensed) DOFs
/// to their own loads through (K_mm + iωC_mm)⁻¹. Compared with the direct solve
/// in tests and docs/accuracy.md. An undamped mode at ω is driven (the response unbounded)
/// by the same rule as in harmonic_response, against `source_load_norm` (0: the load's own).
HarmonicResponse modal_harmonic_response(const LinearSystem& system, const ModalResult& modes,
                                         const Eigen::VectorXcd& load, double frequency_hz, int mode_count = 0,
                                         double source_load_norm = 0.0);

enum class ResponseQuantity { displacement, velocity, acceleration };
const char* to_string(ResponseQuantity quantity);  ///< "displacement", "velocity", "acceleration"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<ResponseQuantity> response_quantity_from_string(const std::string& word);

/// |X|, |iωX| or |ω²X| of one DOF.
double response_amplitude(const HarmonicResponse& response, int dof, ResponseQuantity quantity);

/// Friction of leaf springs against one mode (springs digest §2.3; two-axle digest (169a)):
/// Σ R·|δ| over the friction stages for a unit modal amplitude, with R = φ × the load the
/// stage carries and δ the stage's share of its element's stretch. Over a cycle of amplitude
/// q friction dissipates 4·q·(this); a harmonic modal force F₀ puts in π·F₀·q at resonance.
double modal_friction_work(const LinearSystem& system, const Eigen::VectorXd& shape);

/// Whether any spring stage of the vehicle has leaf friction (relative_friction > 0).
bool has_leaf_friction(const LinearSystem& system);

/// The system with each leaf-friction stage replaced, at circular frequency ω, by the viscous
/// damper across its element that dissipates as much per cycle when the element stretches by
/// `stretch_amplitude`: c = 4R·s/(πωX), R = φ × load, s the stage's share of the stretch.
/// Only when a user asks for it: Coulomb friction is not viscous, and the answer depends on
/// the amplitude chosen.
LinearSystem with_equivalent_friction_damping(const LinearSystem& system, double omega, double stretch_amplitude);
/// The same with a stretch amplitude per element (m, indexed like vehicle.elements); an
/// element with 0 (or beyond the vector) keeps its friction out of the linear model.
LinearSystem with_equivalent_friction_damping(const LinearSystem& system, double omega,
                                              const std::vector<double>& stretch_per_element);

struct OutputRequest {
  int dof = 0;  ///< index into LinearSystem::dofs
  ResponseQuantity quantity = ResponseQuantity::displacement;
  /// false: the curve's phases_deg stays empty. Amplitude-only sweeps (peak refinement, the
  /// sweep benchmark's first row) save an arg x per speed and 8 bytes per speed of output.
  bool phase = true;
};

/// A resonance as one requested output sees it (CriticalSpeedOptions::outputs).
struct ResonanceAtOutput {
  std::string output;  ///< DOF label
  ResponseQuantity quantity = ResponseQuantity::displacement;
  bool unbounded = false;  ///< a resonant (undamped, driven) mode moves this DOF
  /// Steady amplitude (m, m/s, m/s²; rad-based for rotations) of this output at the critical
  /// speed when bounded, 0 when unbounded; where the resonant modes do not move the DOF, the
  /// finite rest of the response.
  double amplitude = 0.0;
  /// Growth of this output's amplitude per half period without friction or damping: π F₀/(2λ)
  /// times the entry at the DOF of the combination the load drives in the resonance's cluster
  /// (as CriticalSpeed::growth_per_half_period), times ω or ω² for velocity or acceleration; 0
  /// where it does not move the DOF. A DOF only a near-coincident neighbour moves shows that
  /// neighbour's growth while its (large, finite) amplitude is not unbounded.
  double growth_per_half_period = 0.0;
};

/// One resonance of one source harmonic with one mode, inside the speed range.
struct CriticalSpeed {
  double speed = 0.0;           ///< m/s
  int source = 0;               ///< index into the sources given
  std::string source_kind;      ///< ExcitationSource::kind()
  int harmonic = 1;
  int mode = 0;                 ///< 1-based mode index
  std::string mode_name;
  double frequency_hz = 0.0;    ///< natural frequency of the mode = excitation frequency
  std::string output;           ///< DOF label reported: the mode's most energetic DOF
  bool unbounded = false;       ///< undamped: the amplitude grows without limit
  double amplitude = 0.0;       ///< steady amplitude of `output` (m or rad) when bounded
  /// Growth of `output` per half period at resonance without friction or damping
  /// (π F₀/(2λ) in the modal coordinate) of the combination the load drives in the cluster of
  /// modes within 1 % of this frequency, each neighbour weighted 1 − gap/1 % (only the
  /// eigenspace itself when no other mode is that close): continuous as modes coincide.
  double growth_per_half_period = 0.0;
  /// Decrease per half period that leaf-spring friction imposes on that combination
  /// (2 Σ R|δ| / λ, each stage over the amplitude of its own stretch); 0 without friction.
  double friction_decrement_per_half_period = 0.0;
  /// Friction stops the resonance: the growth per half period does not exceed the decrement
  /// (Den Hartog's criterion, the book's (169a) without its static term).
  bool friction_stops = false;
  /// Factor on the source amplitude (dip depth, eccentricity, …) at which friction would no
  /// longer stop the resonance; 0 without friction (any amplitude grows).
  double friction_threshold_scale = 0.0;
  /// The same resonance at every output of CriticalSpeedOptions::outputs, in that order.
  std::vector<ResonanceAtOutput> outputs;
};

struct CriticalSpeedOptions {
  double min_speed = 0.0;  ///< m/s, > 0
  double max_speed = 0.0;  ///< m/s
  /// > 0: leaf friction also acts as equivalent viscous damping for this element stretch
  /// amplitude (m), so resonances get finite amplitudes; 0: friction only in the criterion.
  double friction_reference_amplitude = 0.0;
  /// Outputs every critical speed also reports (CriticalSpeed::outputs: amplitude and growth
  /// per half period at each); empty: only the mode's own `output`. A DOF out of range of the
  /// system is refused by find_critical_speeds (std::invalid_argument).
  std::vector<OutputRequest> outputs;
  /// Returns false and explains in *why when an option is out of range: 0 < min_speed ≤
  /// max_speed, finite; friction_reference_amplitude finite and ≥ 0; every output's DOF ≥ 0.
  bool is_valid(std::string* why) const;
};

/// Every resonance V = Λ·f/k in the range, for every source, harmonic and oscillatory mode
/// that the source loads, sorted by speed. A harmonic loads a mode when its modal force exceeds
/// 1e-9·‖φ‖ times the source's total load √(Σ_k ‖Q_k‖²) at that speed (as harmonic_response
/// decides): symmetry zeros and harmonics that are round-off of their source give no row. The
/// friction criterion of a row is evaluated on the load's projection onto the modes within 1 %
/// of its frequency (docs/scenes.md), so it is continuous where modes coincide. Throws
/// std::invalid_argument for invalid options or an output DOF out of range. `summary`, if
/// given, receives the method, the checks (resonances found, driven, stopped by friction) and
/// the stage times.
std::vector<CriticalSpeed> find_critical_speeds(const LinearSystem& system, const ModalResult& modes,
                                                const std::vector<const ExcitationSource*>& sources,
                                                const CriticalSpeedOptions& options,
                                                AnalysisSummary* summary = nullptr);

/// The speeds of a sweep, m/s, ascending or as given: immutable, and shared rather than copied
/// by the curves of one sweep (a sweep of 10⁴ speeds and 8 curves would otherwise spend more
/// time copying its grid and faulting in the copies than computing the responses).
class SpeedGrid {
 public:
  SpeedGrid() = default;
  SpeedGrid(std::vector<double> speeds)  // NOLINT: implicit, a curve's speeds can be set from a vector
      : values_(std::make_shared<const std::vector<double>>(std::move(speeds))) {}
  SpeedGrid(std::initializer_list<double> speeds) : SpeedGrid(std::vector<double>(speeds)) {}
  const std::vector<double>& values() const { return values_ ? *values_ : no_speeds(); }
  std::size_t size() const { return values().size(); }
  bool empty() const { return values().empty(); }
  double operator[](std::size_t i) const { return values()[i]; }
  double front() const { return values().front(); }
  double back() const { return values().back(); }
  std::vector<double>::const_iterator begin() const { return values().begin(); }
  std::vector<double>::const_iterator end() const { return values().end(); }
  friend bool operator==(const SpeedGrid& a, const SpeedGrid& b) { return a.values() == b.values(); }
  friend bool operator!=(const SpeedGrid& a, const SpeedGrid& b) { return !(a == b); }

 private:
  static const std::vector<double>& no_speeds() {
    static const std::vector<double> none;
    return none;
  }
  std::shared_ptr<const std::vector<double>> values_;
};

/// Amplitude of one output against speed for one source: at each speed the sum over the
/// source's harmonics of the harmonic amplitudes (the bound of the peak of their sum; exact
/// for a one-harmonic source). Speeds where the response is unbounded are flagged.
struct AmplitudeCurve {
  int source = 0;
  std::string output;
  ResponseQuantity quantity = ResponseQuantity::displacement;
  SpeedGrid speeds;
  std::vector<double> amplitudes;  ///< m, m/s or m/s² (rad for rotations); 0 where unbounded
  std::vector<bool> unbounded;
  /// Phase of the output's first harmonic against the source's input at its leading wheel
  /// (its first force for an unbalance), degrees in (−180, 180]; 0 where unbounded or where
  /// the source has no input. With the amplitude of harmonic 1 this is the FRF (displacement
  /// transmissibility or receptance, ×iω for velocity, ×−ω² for acceleration). Empty when
  /// the output was requested without its phase (OutputRequest::phase).
  std::vector<double> phases_deg;
};

/// The input that AmplitudeCurve::phases_deg are measured against, at unit load scale: harmonic
/// 1 at the source's leading wheel (smallest delay; its largest component) or, with no wheel
/// input, its first force. 0 when the source has no input. A speed where the load scale s(ω)
/// is negative turns the reference by π.
std::complex<double> phase_reference(const LinearSystem& system, const ExcitationSource& source);

/// One curve per output, from one direct solve per speed and harmonic (or the modal
/// expansion that agrees with it). The curves share `speeds` (a vector converts, copied
/// once); sweeps of several sources over one grid can pass one SpeedGrid and share it too.
/// `friction_reference_amplitude` as in CriticalSpeedOptions. Throws std::invalid_argument for
/// an output DOF out of range or a speed not positive and finite. `summary`, if given,
/// receives the path taken (modal superposition, complex modes, or direct solves), the
/// unbounded speeds found and the stage times.
std::vector<AmplitudeCurve> amplitude_curves(const LinearSystem& system, const ModalResult& modes,
                                             const ExcitationSource& source, int source_index,
                                             const std::vector<OutputRequest>& outputs,
                                             const SpeedGrid& speeds,
                                             double friction_reference_amplitude = 0.0,
                                             AnalysisSummary* summary = nullptr);

/// Dynamic deflection of one suspension element against speed for one source: the amplitude
/// of its vertical stretch, upper end relative to lower end (relative to the track under it
/// for a track element), summed over the source's harmonics as in AmplitudeCurve. This is
/// the deflection the book limits (springs digest §5); a stage in series takes the share
/// k_element/k_stage of it.
struct DeflectionCurve {
  int source = 0;
  int element = 0;                 ///< index into vehicle.elements
  SpeedGrid speeds;
  std::vector<double> amplitudes;  ///< m; 0 where unbounded
  /// N: the force through the element's spring stages, Σ_k |(k_e + iω c_k) y_k| with k_e
  /// their series stiffness and c_k the linearised leaf friction, which acts inside a stage
  /// and so passes through the others (a coil in series with a leaf spring deflects by this
  /// over its own stiffness); 0 where unbounded
  std::vector<double> spring_forces;
  std::vector<bool> unbounded;     ///< an undamped resonance that stretches the element
};
/// One curve per element, from one direct solve per speed and harmonic. Leaf friction of
/// element k acts as the equivalent viscous damper for a stretch amplitude of
/// `friction_reference_stretch[k]` (m; see with_equivalent_friction_damping); 0, or no entry,
/// leaves that element's friction out of the linear model. Throws std::invalid_argument for an
/// element out of range or a speed not positive and finite. `summary`, if given, receives the
/// method, the unbounded points found and the stage times.
std::vector<DeflectionCurve> element_deflection_curves(const LinearSystem& system, const ModalResult& modes,
                                                       const ExcitationSource& source, int source_index,
                                                       const std::vector<int>& elements,
                                                       const std::vector<double>& speeds,
                                                       const std::vector<double>& friction_reference_stretch = {},
                                                       AnalysisSummary* summary = nullptr);
/// The largest amplitude of one output between `low` and `high` (a bracket holding one
/// damped resonance peak), by golden-section search until the bracket is narrower than
/// `relative_tolerance` × speed. Each evaluation is one direct solve per source harmonic.
struct Peak {
  double speed = 0.0;      ///< m/s
  double amplitude = 0.0;  ///< as in AmplitudeCurve
  int evaluations = 0;
  bool unbounded = false;  ///< an undamped resonance: no finite peak
};

/// Throws std::invalid_argument unless 0 < low < high and relative_tolerance > 0. `summary`, if
/// given, receives the method, the evaluations and the final bracket, and the stage time.
Peak refine_peak(const LinearSystem& system, const ModalResult& modes, const ExcitationSource& source,
                 const OutputRequest& output, double low, double high, double relative_tolerance,
                 double friction_reference_amplitude = 0.0, AnalysisSummary* summary = nullptr);

}  // namespace railmodal
