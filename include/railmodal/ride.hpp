// railmodal — ride on random track: the response spectra of a vehicle running on track whose
// irregularity is a stationary random process given by its power spectral density, and the
// ride indices engineers sign off on (RMS, EN 12299 weighted RMS and its 95th percentile,
// Sperling's Wz, the mean comfort N_MV).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     using namespace railmodal;
//     const LinearSystem system =
//         assemble(load_vehicle("data/vehicles/manchester_benchmark_coach.toml"), DofSet::vertical);
//     TrackIrregularitySpectra track;  // ORE B176 low level, wavelengths 3 … 100 m
//     track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level,
//                                                    {2 * 3.14159265358979 / 100, 2 * 3.14159265358979 / 3});
//     RideOptions options;
//     options.speeds = {100 / 3.6, 200 / 3.6};
//     const RideResult ride = solve_ride(system, track, default_ride_outputs(system), options);
//     for (const RideAtSpeed& at : ride.speeds)
//       for (std::size_t i = 0; i < ride.outputs.size(); ++i)
//         std::cout << at.speed * 3.6 << " km/h  " << ride.outputs[i].name << ": RMS "
//                   << at.outputs[i].rms << "\n";
//   }
//
// The method (docs/ride.md, "The response to random track"): the irregularity components
// (vertical level, alignment, cross-level) are uncorrelated, stationary and one-sided in
// wavenumber (track_spectrum.hpp). At speed V every track input (wheel) i at x_i meets the
// same track x_i/V later than one at x = 0, so an output's frequency response to component c is
// H_c(f) = Σ_i h_{c,i}(f)·e^{iωx_i/V} (the wheelbase and bogie-spacing filters), and its
// one-sided PSD S_out(f) = Σ_c |H_c(f)|² G_c(f), G_c(f) = (2π/V) S_c(2πf/V). The RMS is
// √∫S_out df over the frequency grid.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/comfort_weighting.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/response.hpp"
#include "railmodal/summary.hpp"
#include "railmodal/track_spectrum.hpp"

namespace railmodal {

/// The irregularity of one track: each component present is a spectrum of its kind
/// (TrackSpectrum::irregularity() must match), the components uncorrelated.
struct TrackIrregularitySpectra {
  std::optional<TrackSpectrum> vertical_level;
  std::optional<TrackSpectrum> alignment;
  std::optional<TrackSpectrum> cross_level;
};

/// A direction of motion or force in the vehicle frame.
enum class RideAxis { longitudinal, lateral, vertical };
const char* to_string(RideAxis axis);  ///< "longitudinal", "lateral", "vertical"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<RideAxis> ride_axis_from_string(const std::string& word);

/// One quantity the ride analysis reports.
struct RideOutput {
  enum class Kind {
    point,               ///< motion of a body-fixed point (body, point, axis, quantity)
    element_deflection,  ///< an element's deflection along `axis` (upper end relative to lower), m
    /// the force an element exerts on its upper body along `axis`, N: −(k + iωc)·deflection
    /// (spring + viscous damper, the linearised leaf friction and series dampers included);
    /// vertically the change of its compression load
    element_force,
    /// a wheelset's wheel–rail force along `axis`, N, the sum of both wheels, up on the
    /// wheelset: the forces of the elements standing on it plus its mass times the rail's
    /// acceleration (vertical); laterally the creep contact's force (with the wheelsets' lateral
    /// motion free; frequency domain only); longitudinally refused (zero in the linear contact).
    wheel_rail_force,
  };
  std::string name;  ///< for reports: "floor over front bogie, vertical"; unique within a request
  Kind kind = Kind::point;
  std::string body;                                 ///< point: the body's name
  Eigen::Vector3d point{0.0, 0.0, 0.0};             ///< point: m, vehicle frame
  std::string element;                              ///< element_*: element name; wheel_rail_force: wheelset body
  RideAxis axis = RideAxis::vertical;
  ResponseQuantity quantity = ResponseQuantity::acceleration;  ///< point only
  /// The axes a point's acceleration is read along (docs/ride.md, "Lateral acceleration's frame").
  enum class Frame {
    /// An accelerometer fixed to the body (EN 12299, ISO 2631-1: transducers on the floor, along
    /// the body's axes): the specific force, the acceleration plus the component of gravity along
    /// the tilted axis, laterally ÿ + g·φ (φ the body's roll), longitudinally ẍ − g·θ (θ its
    /// pitch, positive nose down: the vehicle frame's right-handed rotation about y), vertically z̈.
    body,
    /// The acceleration in the track's (inertial) frame, without gravity.
    track,
  };
  /// Point accelerations only; a displacement or velocity differs only to second order and is
  /// the same in both.
  Frame frame = Frame::body;
};
const char* to_string(RideOutput::Frame frame);  ///< "body", "track"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<RideOutput::Frame> ride_frame_from_string(const std::string& word);
/// Whether an accelerometer's gravity term g·φ (lateral) or −g·θ (longitudinal) enters `output`:
/// a point's lateral or longitudinal acceleration read in the body frame.
bool reads_gravity(const RideOutput& output);
const char* to_string(RideOutput::Kind kind);  ///< "point", "element_deflection", "element_force", "wheel_rail_force"
/// Inverse of to_string; std::nullopt for an unknown word.
/// Also reads the hyphenated words of files written before 2026-11-27 ("element-force", ...).
std::optional<RideOutput::Kind> ride_output_kind_from_string(const std::string& word);
/// The SI unit of an output's values: "m", "m/s", "m/s²" (a point's displacement, velocity,
/// acceleration; an element's deflection in m) or "N" (forces).
std::string unit_of(const RideOutput& output);

/// The floor points a ride report looks at when none are named: on the car body (the body with
/// the largest mass), above each bogie centre (or axle, for a two-axle wagon), at mid-car, and
/// 1 m in from each end of the body, vertical and (when the body moves sideways) lateral
/// acceleration. The body's ends are those of its bending beam (Body::bending) when it has one;
/// otherwise the vehicle does not give them, and the last two points lie 1 m inboard of the
/// outermost elements on the body and are named so ("floor 1 m inboard of front support").
/// Height: the body's floor, Body::floor_height. A body without one has the points at its
/// reference point's height (for the templates the plane of its springs, below a real floor,
/// where a lateral acceleration lacks the roll's share −h·φ̈), and solve_ride and simulate_ride
/// then say so in their notes, once.
std::vector<RideOutput> default_ride_outputs(const LinearSystem& system);

struct RideOptions {
  std::vector<double> speeds;    ///< m/s, each > 0 and finite; at least one
  double min_frequency = 0.1;    ///< Hz, > 0: the grid's lower end
  double max_frequency = 80.0;   ///< Hz, > min_frequency: the grid's upper end
  /// Base grid: this many log-spaced points per decade (≥ 10) …
  int points_per_decade = 100;
  /// … refined so that each mode in the band has at least this many points within its
  /// half-power bandwidth (≥ 1; the refinement is what makes a lightly damped peak's area
  /// converge: docs/accuracy.md, "Ride: frequency grid").
  int points_per_bandwidth = 8;
  /// 0: H(f) by a direct solve of the dynamic stiffness at every frequency (exact); n > 0:
  /// modal superposition over the n lowest undamped modes (truncation: docs/accuracy.md).
  int modes = 0;
  /// b, half the distance between the contact points, m, for a cross-level height difference
  /// Δz to become the roll angle Δz/(2b); 0: the wheelsets' contact_half_spacing where the
  /// vehicle has wheelsets, else 0.75 m (standard gauge, 1.5 m between contact points).
  double contact_half_spacing = 0.0;
  /// r0, m: the rail top lies r0 below the axle plane (the vehicle frame's z = 0), and the
  /// cross-level rolls the rails about it, so a track input at height z moves sideways by
  /// −θ·(z + r0) (docs/ride.md, "The track"); 0: the rolling_radius of the wheelset the input's
  /// element stands on (else the first wheelset's), and without wheelsets 0 with a note.
  double rolling_radius = 0.0;
  /// T, s: the averaging time of the weighted RMS whose 95th percentile is estimated (EN 12299:
  /// 5 s).
  double percentile_window = 5.0;
  /// Leaf friction in the vehicle: linearised statistically (an equivalent viscous damping
  /// from the RMS relative velocity across each friction element, iterated to consistency),
  /// with this relative tolerance on the RMS velocities and at most friction_iterations passes.
  double friction_tolerance = 1e-6;
  int friction_iterations = 50;
  int threads = 1;  ///< ≥ 1: speeds shared among threads
  /// Keep every output PSD on the grid (RideOutputAtSpeed::psd): reports plot them. Off, only
  /// the indices are kept (studies).
  bool keep_spectra = true;
  /// Only each output's RMS and weighted RMS, for a user (a speed scan, a study's metric) who
  /// needs no more: no modal shares (RideOutputAtSpeed::modes empty, cross_term_variance σ²),
  /// no Sperling Wz, P95 estimate or N_MV (RideAtSpeed::comfort empty), no direct_variance and
  /// no grid error estimate (grid_error_estimate 0, its check left out of the summary; a note
  /// says so). The RMS and weighted RMS are bit for bit the full solve's (docs/ride.md,
  /// "Performance").
  bool rms_only = false;
  bool is_valid(std::string* why) const;
};

/// One mode's share of an output's variance. With H = Σ_j H_j (H_j the modal term of mode j),
/// σ² = Σ_j ∫|H_j|²G df + Σ_{j≠k} ∫Re(H_j H_k*)G df: `variance` is the first (the mode alone),
/// and the cross terms of all pairs are RideOutputAtSpeed::cross_term_variance, so the shares
/// and the cross term add up to σ² exactly. Where part of H belongs to no oscillatory mode (the
/// track's own displacement in a track element's deflection or force, rigid-body coordinates),
/// that part and its cross terms are in cross_term_variance too: it is σ² − Σ_j variance.
struct ModalContribution {
  int mode = 0;             ///< index into RideResult::modes
  double variance = 0.0;    ///< unit² of the output
  double share = 0.0;       ///< variance / σ²
};

/// One output at one speed.
struct RideOutputAtSpeed {
  /// True when the vehicle has an undamped mode the track excites in the band: its RMS is
  /// unbounded and every figure below is absent (NaN never appears).
  bool unbounded = false;
  double rms = 0.0;  ///< in the output's unit (m, m/s, m/s², N), over the grid's band
  /// Acceleration at a point only: the RMS of the EN 12299 weighted acceleration (Wb vertical,
  /// Wd lateral and longitudinal), m/s².
  std::optional<double> weighted_rms;
  /// Acceleration at a point, vertical or lateral: Sperling's Wz from the B-weighted RMS
  /// (the filter form: sperling_wz_from_weighted_rms).
  std::optional<double> sperling_wz;
  /// Acceleration at a point: the 95th percentile of the weighted RMS over percentile_window,
  /// estimated for a stationary Gaussian process (chi-square with ν ≈ 2T(∫S)²/∫S²). An
  /// estimate, labelled so in every report.
  std::optional<double> p95_estimate;
  std::vector<ModalContribution> modes;  ///< largest first; empty when unbounded
  double cross_term_variance = 0.0;      ///< σ² − Σ modes' variance (see ModalContribution)
  /// The variance of the output's direct track term alone, ∫|D|²G df, unit² (0 without one):
  /// the part no mode carries, −k·u in the force of an element standing on the track. It is
  /// inside cross_term_variance with its cross terms; where it and the modes cancel (a spring
  /// force at low frequency) σ² is small and a mode's share can read far above 100 %, so the
  /// reports show this term beside the shares.
  double direct_variance = 0.0;
  Eigen::VectorXd psd;  ///< one-sided, unit²/Hz on RideResult::frequencies (keep_spectra)
};

/// N_MV at one floor point from the estimated P95 of its axes (en12299_nmv); an axis without an
/// output counts as zero and is named in `missing_axes`.
struct RideComfortAtPoint {
  std::string body;
  Eigen::Vector3d point{0.0, 0.0, 0.0};
  double nmv_estimate = 0.0;
  std::vector<RideAxis> missing_axes;
};

struct RideAtSpeed {
  double speed = 0.0;                       ///< m/s
  std::vector<RideOutputAtSpeed> outputs;   ///< in RideResult::outputs order
  std::vector<RideComfortAtPoint> comfort;  ///< per distinct point with acceleration outputs
  /// Input PSDs G_c(f) at this speed on the grid, m²/Hz, in the order vertical level,
  /// alignment, cross-level (only the components present; keep_spectra).
  std::vector<Eigen::VectorXd> input_psd;
};

struct RideMode {
  std::string name;           ///< "body bounce"
  double frequency_hz = 0.0;  ///< undamped natural frequency
};

struct RideResult {
  std::vector<RideOutput> outputs;
  Eigen::VectorXd frequencies;  ///< Hz, the grid, increasing
  std::vector<RideMode> modes;  ///< the undamped modes (names, frequencies), lowest first
  std::vector<RideAtSpeed> speeds;
  /// How friction was treated: "none in the vehicle", or "statistical linearisation: …
  /// converged in N passes" (never the harmonic equivalence of periodic inputs).
  std::string friction_treatment;
  /// The grid's integration error estimate: the largest relative change of any RMS between
  /// the grid and its every-other-point subset (a bound that halving the grid would cause).
  double grid_error_estimate = 0.0;
  std::vector<std::string> notes;  ///< what a reader must know (undamped modes, truncation, …)
  AnalysisSummary summary;
  /// The track spectra's names (TrackSpectrum::name()) in RideAtSpeed::input_psd order, for
  /// the report's legend; empty: the report says "input 1", "input 2", …
  std::vector<std::string> inputs;
  /// The RMS of each track component over its own band (TrackSpectrum::rms()), in `inputs`
  /// order: m (cross-level: the height difference Δz).
  std::vector<double> input_rms;
  /// Solved with RideOptions::rms_only: each output's RMS and weighted RMS, none of the other
  /// indices (a note says which). The reports and the Python binding leave the skipped indices
  /// out rather than show them empty.
  bool rms_only = false;
};

/// Whether `result` holds a grid error estimate: not when solved with rms_only, nor when no
/// output has a bounded, nonzero RMS at any speed (RideResult::grid_error_estimate is then 0, not
/// an estimate; the reports write "no grid error estimate", JSON null, Python None).
bool has_grid_error_estimate(const RideResult& result);

/// The ride of `system` on `track` at every speed of `options`. Throws std::invalid_argument for invalid options, an
/// output that names no body, element or wheelset of the system (naming it and the valid names), an output the system
/// cannot move (a lateral output on vertical degrees of freedom), a spectrum whose kind does not match its slot, a
/// component that reaches no degree of freedom (alignment on a vertical model), a component whose temporal band lies
/// wholly outside the grid at a speed, no component at all, an element on the track through a series damper, and what the ride does not model yet
/// on wheelsets: cross-level with lateral degrees of freedom (the rails' roll through the contact), and a
/// lateral or longitudinal wheel-rail-force output. The refusals of one component (it reaches no degree of freedom,
/// its band is outside the grid, cross-level on such wheelsets) are an IrregularityComponentError (track_spectrum.hpp)
/// that says which. Where the system holds wheelsets' lateral motion the linear
/// creep contact (contact_matrices) is assembled at each speed and alignment acts through it (docs/ride.md, "Lateral
/// ride through the creep forces"); above the linear critical speed every output the growing motion moves is
/// `unbounded` (one it does not move, such as a vertical one decoupled from the lateral motions, keeps its number) and
/// the notes name the motion and the linear critical speed. Throws
/// railmodal::NumericalError naming the frequency where the
/// dynamic stiffness is singular off an undamped mode. An undamped excited mode is an answer (`unbounded`), no throw.
RideResult solve_ride(const LinearSystem& system, const TrackIrregularitySpectra& track,
                      const std::vector<RideOutput>& outputs, const RideOptions& options = {});

}  // namespace railmodal
