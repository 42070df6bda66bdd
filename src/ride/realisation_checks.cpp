// check_ride_realisation and its check (a), the exact bin check of a periodic run; (b) is in
// welch_check.cpp. Derivations: docs/ride.md, "Realisations".
#include "ride/realisation_checks.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "railmodal/ride.hpp"
#include "require_valid.hpp"
#include "ride/ride_state_space.hpp"
#include "ride/track_under_wheels.hpp"
#include "spectrum/real_fft.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal::ride {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Images summed on each side for the state's share: with sinc² ~ 1/j² and the state's
// response ~ 1/j they fall as 1/j³, so 16 leave about 1/16² of the images' share, itself
// (q/N)²/m² of the line at most.
constexpr int kAliases = 16;

using Complex = std::complex<double>;

// The state's share of every output's response to one track component (at the leading
// wheel), from the state space diagonalised once: Ls(sI − A)⁻¹B ŵ, ŵ the wheels' inputs with
// their lags. It falls as 1/s, so with the interpolation's sinc² its images fall as 1/j³.
// The outputs' direct part, (Lw + s Ld)ŵ, does not fall: its images are summed exactly
// instead, by Poisson's formula, as the DFT of Lw w + Ld ẇ at the samples (see
// exact_bin_error).
class ComponentResponse {
 public:
  ComponentResponse(const RideStateSpace& model, const std::vector<OutputRow>& rows, const TrackUnderWheels& track,
                    TrackIrregularity component, double speed)
      : track_(track), component_(component), speed_(speed) {
    const Eigen::EigenSolver<Eigen::MatrixXd> eigen(model.A);
    if (eigen.info() != Eigen::Success) throw std::runtime_error("exact bin check: the state matrix has no eigenvectors");
    poles_ = eigen.eigenvalues();
    const Eigen::MatrixXcd V = eigen.eigenvectors();
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(V);
    modal_input_ = lu.solve(model.B.cast<Complex>());
    for (const OutputRow& row : rows) modal_output_.push_back(row.Ls.cast<Complex>() * V);
  }

  // ŵ at f for a unit component at the leading wheel.
  Eigen::VectorXcd inputs(double frequency) const {
    const double omega = 2.0 * kPi * frequency;
    Eigen::VectorXcd w = Eigen::VectorXcd::Zero(3 * track_.inputs());
    for (int i = 0; i < track_.inputs(); ++i) {
      const Complex lag = std::polar(1.0, -omega * track_.lag(i) / speed_);
      if (component_ == TrackIrregularity::alignment) w(3 * i + 1) = lag;
      if (component_ == TrackIrregularity::vertical_level) w(3 * i + 2) = lag;
      if (component_ == TrackIrregularity::cross_level) w.segment<3>(3 * i) = lag * track_.cross_level(i).cast<Complex>();
    }
    return w;
  }

  Complex at(size_t output, double frequency) const {
    const Complex s(0.0, 2.0 * kPi * frequency);
    const Eigen::VectorXcd w = inputs(frequency);
    const Eigen::VectorXcd modal = (modal_input_ * w).cwiseQuotient((s - poles_.array()).matrix());
    return (modal_output_[output] * modal)(0);
  }

 private:
  const TrackUnderWheels& track_;
  TrackIrregularity component_;
  double speed_;
  Eigen::VectorXcd poles_;
  Eigen::MatrixXcd modal_input_;
  std::vector<Eigen::RowVectorXcd> modal_output_;
};

Eigen::VectorXcd dft(const Eigen::VectorXd& x) {
  spectrum::RealFft fft(x.size());
  fft.input() = x;
  fft.execute();
  return fft.output();
}

double sinc_squared(double x) {
  if (x == 0.0) return 1.0;
  const double s = std::sin(kPi * x) / (kPi * x);
  return s * s;
}

}  // namespace

double exact_bin_error(const LinearSystem& system, const TrackGeometry& geometry,
                       const RideSimulationResult& simulated, const RideSimulationOptions& options) {
  const RideStateSpace model = ride_state_space(system);
  const std::vector<OutputRow> rows = output_rows(system, model, simulated.outputs);
  const TrackUnderWheels track(system, geometry,
                               cross_level_directions(system, options.contact_half_spacing, options.rolling_radius));
  const Eigen::Index n = static_cast<Eigen::Index>(std::llround(track.end() / geometry.step)) + 1;
  const Eigen::Index ne = simulated.time.size();
  if (!geometry.periodic || ne % n != 0)
    throw std::invalid_argument("exact bin check: the run must cover one period of a periodic geometry");
  const double length = static_cast<double>(n) * geometry.step, f0 = options.speed / length;
  const double start = track.span() + options.speed * simulated.time(0);  // ξ₀

  struct Component {
    TrackIrregularity kind;
    const Eigen::VectorXd* profile;
  };
  std::vector<Component> components;
  if (geometry.vertical_level.size()) components.push_back({TrackIrregularity::vertical_level, &geometry.vertical_level});
  if (geometry.alignment.size()) components.push_back({TrackIrregularity::alignment, &geometry.alignment});
  if (geometry.cross_level.size()) components.push_back({TrackIrregularity::cross_level, &geometry.cross_level});

  std::vector<Eigen::VectorXcd> predicted(rows.size(), Eigen::VectorXcd::Zero(n / 2));
  for (const Component& c : components) {
    const Eigen::VectorXcd X = dft(*c.profile);
    const ComponentResponse response(model, rows, track, c.kind, options.speed);
    for (Eigen::Index q = 1; q < n / 2; ++q) {
      if (std::abs(X(q)) == 0.0) continue;
      for (int j = -kAliases; j <= kAliases; ++j) {
        const double k = static_cast<double>(q) + static_cast<double>(j) * static_cast<double>(ne);
        const Complex image = X(q) / static_cast<double>(n) * sinc_squared(k / static_cast<double>(n)) *
                              std::polar(1.0, 2.0 * kPi * k * start / length) * static_cast<double>(ne);
        for (size_t o = 0; o < rows.size(); ++o) predicted[o](q) += response.at(o, k * f0) * image;
      }
    }
  }
  // The direct part at the samples: Σ_j (Lw + s_j Ld)ŵ(k_j)(X_q/N)sinc²(k_j/N)e^{2πik_jξ₀/L}
  // summed over all j is the DFT of Lw w + Ld ẇ sampled from the interpolated track.
  Eigen::VectorXd w, dw;
  Eigen::MatrixXd direct(ne, static_cast<Eigen::Index>(rows.size()));
  for (Eigen::Index k = 0; k < ne; ++k) {
    const double position = start + options.speed * simulated.time_step * static_cast<double>(k);
    track.displacement(position, &w);
    track.slope(position, &dw);
    for (size_t o = 0; o < rows.size(); ++o)
      direct(k, static_cast<Eigen::Index>(o)) = rows[o].Lw.dot(w) + options.speed * rows[o].Ld.dot(dw);
  }
  for (size_t o = 0; o < rows.size(); ++o)
    predicted[o] += dft(direct.col(static_cast<Eigen::Index>(o))).head(n / 2);

  double worst = 0.0;
  for (size_t o = 0; o < rows.size(); ++o) {
    const Eigen::VectorXcd Y = dft(simulated.histories[o].values);
    const double scale = predicted[o].cwiseAbs().maxCoeff();
    if (scale == 0.0) continue;
    worst = std::max(worst, (Y.segment(1, n / 2 - 1) - predicted[o].segment(1, n / 2 - 1)).cwiseAbs().maxCoeff() / scale);
  }
  return worst;
}

}  // namespace railmodal::ride

namespace railmodal {
namespace {

// The band of temporal frequencies the realisation's spectra cover at `speed`.
std::pair<double, double> temporal_band(const TrackIrregularitySpectra& track, double speed) {
  double low = INFINITY, high = 0.0;
  for (const auto* s : {&track.vertical_level, &track.alignment, &track.cross_level})
    if (*s) {
      low = std::min(low, (*s)->band().low * speed / (2.0 * ride::kPi));
      high = std::max(high, (*s)->band().high * speed / (2.0 * ride::kPi));
    }
  return {low, high};
}

}  // namespace

RideFftChecks check_ride_realisation(const LinearSystem& system, const TrackIrregularitySpectra& track,
                                     const TrackGeometry& geometry, const RideSimulationResult& simulated,
                                     const RideSimulationOptions& options) {
  require_valid(options, "RideSimulationOptions: ");
  RideFftChecks checks;
  StageClock clock(&checks.summary);
  checks.summary.analysis = "FFT checks of a ride realisation";
  checks.summary.method = "(a) DFT of the periodic run against H·X with the interpolation's sinc² and aliases; "
                          "(b) Welch PSD (Hann, half overlap) against its expectation, 95 % chi-square band; "
                          "(c) RMS against solve_ride";
  // (a) a linear scene on a periodic realisation only: a simulated nonlinearity has no H
  if (geometry.periodic && !options.effects.any()) {
    checks.exact_bin_error = ride::exact_bin_error(system, geometry, simulated, options);
    // round-off of the march and the FFTs over N_e samples, and the alias tail: 1e-6
    checks.summary.checks.push_back(
        {"(a) largest relative bin error", *checks.exact_bin_error, 1e-6, *checks.exact_bin_error <= 1e-6});
  }
  clock.lap("exact bin check");
  // (b) every component with both a spectrum and a profile; segments of an eighth of the
  // record (15 segments at half overlap), at most 4096 samples
  int outside = 0, bins = 0;
  for (const auto& [spectrum, profile] :
       {std::make_pair(&track.vertical_level, &geometry.vertical_level), std::make_pair(&track.alignment, &geometry.alignment),
        std::make_pair(&track.cross_level, &geometry.cross_level)}) {
    if (!*spectrum || profile->size() == 0) continue;
    const Eigen::Index segment = std::min<Eigen::Index>(4096, profile->size() / 8 / 2 * 2);
    const ride::WelchCheck welch = ride::welch_band_check(*profile, geometry.step, **spectrum, segment);
    outside += static_cast<int>(std::lround(welch.fraction_outside * welch.bins));
    bins += welch.bins;
    checks.summary.checks.push_back({"(b) " + (*spectrum)->name() + ": largest leakage bias of Welch's estimate",
                                     welch.leakage_bias, INFINITY, true});
  }
  if (bins > 0) checks.fraction_outside_band = static_cast<double>(outside) / bins;
  checks.summary.checks.push_back({"(b) fraction of Welch bins outside the 95 % band (expected 0.05)",
                                   checks.fraction_outside_band, INFINITY, true});
  clock.lap("Welch check");
  // (c) the frequency-domain ride over the band the spectra cover
  RideOptions ride_options;
  ride_options.speeds = {options.speed};
  std::tie(ride_options.min_frequency, ride_options.max_frequency) = temporal_band(track, options.speed);
  ride_options.contact_half_spacing = options.contact_half_spacing;  // one convention (cross_level_directions)
  ride_options.rolling_radius = options.rolling_radius;
  const RideResult ride = solve_ride(system, track, simulated.outputs, ride_options);
  bool bounded = true;
  for (size_t o = 0; o < simulated.outputs.size(); ++o) {
    const RideOutputAtSpeed& at = ride.speeds.front().outputs[o];
    bounded = bounded && !at.unbounded && at.rms > 0.0;
    if (bounded) checks.rms_difference.push_back(simulated.histories[o].rms / at.rms - 1.0);
  }
  if (!bounded) checks.rms_difference.clear();
  // With leaf friction simulated, (c) is what solve_ride's statistical linearisation misses:
  // a figure to report, with no bound.
  const std::string what = options.effects.leaf_friction && ride.friction_treatment != "none in the vehicle"
                               ? ": simulated friction RMS against the statistically linearised one, relative"
                               : ": relative RMS difference";
  for (size_t o = 0; o < checks.rms_difference.size(); ++o)
    checks.summary.checks.push_back({"(c) " + simulated.outputs[o].name + what, checks.rms_difference[o], INFINITY, true});
  clock.lap("RMS against solve_ride");
  return checks;
}

}  // namespace railmodal
