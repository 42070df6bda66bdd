// railmodal — ride on random track in the time domain: a realisation of the track synthesised
// from its spectra (or measured geometry read from a file) run through the simulation with
// exactly the effects a scene names, the EN 12299 indices from the weighted acceleration
// history (5 s RMS values, their 95th percentile, the continuous comfort Cc(t)), and the FFT
// checks that tie the time domain to the frequency-domain ride (ride.hpp).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     using namespace railmodal;
//     TrackIrregularitySpectra track;
//     track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level,
//                                                    {2 * 3.14159265358979 / 100, 2 * 3.14159265358979 / 3});
//     TrackSynthesisOptions synthesis;
//     synthesis.length = 4096.0;  // m
//     synthesis.step = 0.25;      // m
//     synthesis.seed = 7;
//     const TrackGeometry geometry = synthesise_track(track, synthesis);
//     std::cout << geometry.source << ": " << geometry.vertical_level.size() << " samples\n";
//   }
//
// Conventions (docs/ride.md, "Realisations"): a synthesised profile is periodic with period
// `length`, z(x) = Σ_k Re(c_k e^{iΩ_k x}) over Ω_k = 2πk/length inside the band; its Fourier
// coefficients c_k are complex Gaussian (independent normal real and imaginary parts, variance
// S(Ω_k)ΔΩ each, so E z² = Σ S(Ω_k)ΔΩ), not fixed amplitudes with random phases, so that a
// realisation's periodogram scatters as chi-square with 2 degrees of freedom about the target.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/simulation.hpp"
#include "railmodal/summary.hpp"

namespace railmodal {

/// Track geometry sampled every `step` metres from distance 0 along the track.
struct TrackGeometry {
  double step = 0.0;  ///< m
  /// m, one sample per step; an empty vector: that component is absent (taken as zero).
  Eigen::VectorXd vertical_level, alignment, cross_level;
  /// True for a synthesised profile (it repeats every size·step metres: the FFT checks use
  /// this); false for measured geometry.
  bool periodic = false;
  std::string source;  ///< "ORE B176 low, vertical level; 4096 m every 0.25 m; seed 7" or the file
  double length() const;  ///< m, samples × step
};

struct TrackSynthesisOptions {
  double length = 0.0;      ///< m, > 0: the period of the profile (rounded up to whole steps)
  double step = 0.0;        ///< m, > 0: the sample spacing (Nyquist wavenumber π/step)
  std::uint64_t seed = 1;   ///< the same seed gives the same profile on every machine
  bool is_valid(std::string* why) const;
};

/// A realisation of `track` by inverse real FFT (FFTW). Throws std::invalid_argument for
/// invalid options, no component, or a spectrum band the sampling cannot represent (its upper
/// end above the Nyquist wavenumber, or its lower end below 2π/length), naming which: that one
/// an IrregularityComponentError (track_spectrum.hpp) with its component.
TrackGeometry synthesise_track(const TrackIrregularitySpectra& track, const TrackSynthesisOptions& options);

/// Measured track geometry from a CSV file: a header row naming the columns with units
/// (`distance [m]`, and any of `vertical level [m]`, `alignment [m]`, `cross-level [m]`; mm
/// accepted), then rows at a constant distance step. Errors are InputError with file, line and
/// column name.
TrackGeometry load_track_geometry(const std::string& path);

struct RideSimulationOptions {
  double speed = 0.0;      ///< m/s, > 0
  double time_step = 0.0;  ///< s, 0 ≤ step ≤ the geometry's step / speed; 0: 1 ms or that if less (docs/ride.md)
  /// s, ≥ 0: simulated but not evaluated, so the start-up transient is left out.
  double settle_time = 0.0;
  /// Vehicle effects the scene names (SimulationSpec::effects); nothing else is simulated.
  /// They run through the nonlinear simulation on the sampled track, simulated and not
  /// linearised (docs/ride.md, "Friction in time").
  NonlinearEffects effects;
  double window = 5.0;  ///< s: EN 12299's averaging time of the weighted RMS values
  /// b, half the distance between the contact points, m, for a cross-level Δz to become the
  /// roll angle Δz/(2b) (as RideOptions::contact_half_spacing); 0: the wheelsets'
  /// contact_half_spacing where the vehicle has wheelsets, else 0.75 m.
  double contact_half_spacing = 0.0;
  /// r0, m: the rail top below the axle plane, about which cross-level rolls the rails (as
  /// RideOptions::rolling_radius); 0: the wheelsets' rolling_radius, else 0.
  double rolling_radius = 0.0;
  bool is_valid(std::string* why) const;
};

/// One output's history and the indices computed from it.
struct RideHistory {
  Eigen::VectorXd values;           ///< the output's samples after settle_time, in its unit
  Eigen::VectorXd weighted;         ///< acceleration at a point: the EN 12299-weighted samples, m/s²
  Eigen::VectorXd window_rms;       ///< the weighted RMS of each complete window, m/s²
  double rms = 0.0;                 ///< of `values`
  std::optional<double> weighted_rms;  ///< of `weighted`
  std::optional<double> sperling_wz;   ///< from the Sperling-weighted history (filter form)
  /// The 95th percentile of window_rms (EN 12299 over 60 windows of a 5-minute zone; with
  /// fewer windows, over those there are, and a note says so).
  std::optional<double> p95;
  Eigen::VectorXd continuous_comfort;  ///< Cc(t), m/s²: the running 5 s weighted RMS, every sample
};

/// The FFT checks of a realisation (issue 21, item 4).
struct RideFftChecks {
  /// (a) for a periodic realisation and a linear scene: max over bins and outputs of
  /// |X_sim − H·X_track| / max|H·X_track| in the simulated steady state.
  std::optional<double> exact_bin_error;
  /// (b) the fraction of Welch-PSD bins of the realisation outside the 95 % confidence band of
  /// the target spectrum (expected about 5 %).
  double fraction_outside_band = 0.0;
  /// (c) relative difference of the simulated RMS from the frequency-domain RMS, per output
  /// (linear scenes: a check; friction scenes: what the statistical linearisation misses).
  std::vector<double> rms_difference;
  AnalysisSummary summary;
};

struct RideSimulationResult {
  std::vector<RideOutput> outputs;
  /// s: the step used, time_step rounded down to Δx/(mV) for a whole m so that the track's
  /// samples meet every wheel on a fixed phase of the step grid (what makes the linear path
  /// exact for the linearly interpolated track).
  double time_step = 0.0;
  Eigen::VectorXd time;  ///< s, after settle_time
  std::vector<RideHistory> histories;  ///< in `outputs` order
  std::vector<RideComfortAtPoint> comfort;  ///< N_MV from the P95 of the histories
  double window = 5.0;  ///< s: the averaging time of RideHistory::window_rms (RideSimulationOptions::window)
  std::vector<std::string> notes;
  AnalysisSummary summary;
};

/// Runs `system` over `geometry` at options.speed, each wheel meeting the track x_i/V after the
/// leading one, exactly for the linearly interpolated track (docs/ride.md, "Realisations"); a
/// periodic geometry over one period from its periodic steady state, a measured one from rest.
/// Throws std::invalid_argument for invalid options, a geometry too short for the run, an
/// output naming nothing in the system, and for what the time domain does not build yet
/// (element and wheel–rail forces, series dampers, massless DOFs).
RideSimulationResult simulate_ride(const LinearSystem& system, const TrackGeometry& geometry,
                                   const std::vector<RideOutput>& outputs, const RideSimulationOptions& options);

/// The FFT checks of a simulated realisation against the frequency-domain ride of the same
/// system, spectra and outputs at the same speed: (a) when the geometry is periodic, (b) for
/// each component with both a spectrum and a profile, (c) by solve_ride over the band the
/// spectra cover (rms_difference empty when an output is unbounded there). Throws as
/// simulate_ride and solve_ride do.
RideFftChecks check_ride_realisation(const LinearSystem& system, const TrackIrregularitySpectra& track,
                                     const TrackGeometry& geometry, const RideSimulationResult& simulated,
                                     const RideSimulationOptions& options);

}  // namespace railmodal
