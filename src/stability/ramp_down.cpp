// The ramp-down: Dormand–Prince 5(4) with an adaptive step over the speed ramp, and the
// limit-cycle amplitude read off each half cycle (docs/stability.md, "The nonlinear critical
// speed", says what this can and cannot show).
#include "stability/ramp_down.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "railmodal/errors.hpp"
#include "simulate/dormand_prince.hpp"

namespace railmodal::stability {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Local error per step against 1e-10 + 1e-7·|x| in every state (m, rad, m/s, N): fine enough that
// halving both moves the critical speed of the tests by far less than their tolerances.
constexpr double kRelativeTolerance = 1e-7;
constexpr double kAbsoluteTolerance = 1e-10;
// A half cycle whose amplitude falls by less than this fraction from the one before is still on
// the limit cycle: along a slow ramp the branch's own amplitude changes by well under 1% a half
// cycle, a collapse by much more.
constexpr double kOnBranchDecay = 0.005;
// Samples per hunting period at the start speed: the amplitude is the largest sampled |y| of a
// half cycle, so it is low by at most 1 − cos(π/100) ≈ 5e-4 of itself.
constexpr double kSamplesPerPeriod = 100.0;

// The largest step: a hundredth of the shortest kinematic period (Klingel's wavelength over
// the start speed), and never more than 10 ms.
double largest_step(const LateralEquations& e, double start_speed) {
  double step = 0.01;
  for (const WheelsetContact& w : e.wheelsets()) {
    const auto& g = w.geometry;
    if (g.conicity <= 0.0) continue;
    const double wavelength = 2.0 * kPi * std::sqrt(g.rolling_radius * g.contact_half_spacing / g.conicity);
    step = std::min(step, wavelength / start_speed / kSamplesPerPeriod);
  }
  return step;
}

// Follows the half cycles of y: a new one at every change of sign.
class HalfCycles {
 public:
  void add(double y, double speed) {
    if (y * sign_ < 0.0) close();
    if (y != 0.0) sign_ = y > 0.0 ? 1.0 : -1.0;
    if (std::abs(y) > peak_.amplitude) peak_ = {speed, std::abs(y)};
  }
  // The last, unfinished half cycle counts too: an oscillation that stops crossing zero ends there.
  std::vector<LimitCyclePoint> finish() {
    close();
    return std::move(peaks_);
  }

 private:
  void close() {
    if (peak_.amplitude > 0.0) peaks_.push_back(peak_);
    peak_ = {};
  }
  double sign_ = 0.0;
  LimitCyclePoint peak_;
  std::vector<LimitCyclePoint> peaks_;
};

// Where the collapse began. Just after the branch ends the decay per half cycle,
// d = ln(A_prev/A), grows from 0 about linearly as the speed falls (for a linear law,
// d = −Re λ·T/2 with Re λ ∝ V − V_c); the line fitted to the first decays up to four times the
// threshold, extrapolated to d = 0, removes the bias of the threshold itself. The half cycle at
// the branch end stands when there are too few points or the line does not fall to it.
double onset_of_decay(const std::vector<LimitCyclePoint>& peaks, std::size_t last, std::size_t alive) {
  double n = 0, sv = 0, sd = 0, svv = 0, svd = 0;
  for (std::size_t j = last + 1; j < alive; ++j) {
    const double d = std::log(peaks[j - 1].amplitude / peaks[j].amplitude);
    if (d > 4.0 * kOnBranchDecay) break;
    const double v = peaks[j].speed;
    n += 1;
    sv += v;
    sd += d;
    svv += v * v;
    svd += v * d;
  }
  const double fallback = peaks[last].speed;
  if (n < 3) return fallback;
  const double slope = (n * svd - sv * sd) / (n * svv - sv * sv);
  const double intercept = (sd - slope * sv) / n;
  if (!(slope < 0.0)) return fallback;
  const double onset = -intercept / slope;
  return onset >= fallback && onset <= peaks.front().speed ? onset : fallback;
}

// The verdict from the half cycles: the oscillation died out after the last half cycle at or
// above the extinction amplitude; the limit cycle it came from ends at the last half cycle before
// that whose amplitude was not collapsing (walking back over the collapse).
void read_verdict(std::vector<LimitCyclePoint> peaks, double extinction, RampDown* r) {
  std::size_t alive = peaks.size();
  while (alive > 0 && peaks[alive - 1].amplitude < extinction) --alive;
  if (alive == peaks.size() && alive > 0) {
    r->verdict = NonlinearHuntingVerdict::survives_to_end_speed;
    r->curve = std::move(peaks);
    return;
  }
  peaks.resize(alive);
  std::size_t last = alive == 0 ? 0 : alive - 1;
  while (last > 0 && peaks[last].amplitude < (1.0 - kOnBranchDecay) * peaks[last - 1].amplitude) --last;
  if (last == 0) {
    // Decaying from the disturbance all the way: no limit cycle was ever established.
    r->verdict = NonlinearHuntingVerdict::no_limit_cycle_at_start;
  } else {
    r->verdict = NonlinearHuntingVerdict::limit_cycle_dies_out;
    r->critical_speed = onset_of_decay(peaks, last, alive);
    r->amplitude = peaks[last].amplitude;
  }
  r->curve = std::move(peaks);
}

}  // namespace

RampDown ramp_down(const LateralEquations& e, const NonlinearHuntingOptions& o, double ramp_rate) {
  RampDown r;
  r.ramp_rate = ramp_rate;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(e.size());
  x[e.wheelsets().front().lateral] = o.disturbance;
  const double duration = (o.start_speed - o.end_speed) / ramp_rate;
  const double h_max = largest_step(e, o.start_speed);
  const auto speed_at = [&](double t) { return o.start_speed - ramp_rate * t; };
  const auto rhs = [&](double t, const Eigen::VectorXd& state, Eigen::VectorXd* dx) {
    e.derivative(speed_at(t), state, dx);
  };
  HalfCycles cycles;
  cycles.add(e.leading_lateral(x), o.start_speed);
  double t = 0.0, h = h_max / 10.0;
  while (t < duration) {
    h = std::min({h, h_max, duration - t});
    const simulate::DormandPrinceStep step = simulate::dormand_prince_step(rhs, t, x, h);
    double error = 0.0;
    for (Eigen::Index i = 0; i < x.size(); ++i)
      error = std::max(error,
                       std::abs(step.error[i]) /
                           (kAbsoluteTolerance + kRelativeTolerance * std::max(std::abs(x[i]), std::abs(step.y[i]))));
    if (!std::isfinite(error) || h < 1e-12 * std::max(1.0, duration))
      throw NumericalError("solve_nonlinear_hunting: the integration failed at " + std::to_string(speed_at(t)) +
                           " m/s (step " + std::to_string(h) + " s, error " + std::to_string(error) + ")");
    if (error <= 1.0) {
      t += h;
      x = step.y;
      ++r.steps;
      cycles.add(e.leading_lateral(x), speed_at(t));
    }
    // The usual controller of a fifth-order pair, kept within a factor of five either way.
    h *= std::clamp(0.9 * std::pow(std::max(error, 1e-10), -0.2), 0.2, 5.0);
  }
  read_verdict(cycles.finish(), o.extinction_amplitude, &r);
  return r;
}

}  // namespace railmodal::stability
