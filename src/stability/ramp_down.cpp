// The ramp-down: Dormand–Prince 5(4) with an adaptive step over the speed ramp, and the
// limit-cycle amplitude read off each half cycle of every wheelset; the held speed: the same at a
// fixed speed (docs/stability.md, "The nonlinear critical speed", says what this can and cannot
// show).
#include "stability/ramp_down.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include "railmodal/errors.hpp"
#include "simulate/dormand_prince.hpp"
#include "shortest_text.hpp"

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
// A held cycle whose amplitude decays faster than this, per period, is dying; one that decays more
// slowly (or grows) survives. A cycle at this rate takes ln 2/1e-4 ≈ 6900 periods to halve
// (about 50 min of hunting at 2.4 Hz, the bundled wheelset's): a cycle that outlives any run is a
// cycle. The rate is fitted over the hold's second half (hold_rate), so the settling onto a cycle
// just above the fold, which is over by then, does not count as a decay.
constexpr double kHoldRate = 1e-4;

double klingel_wavelength(const WheelsetContact& w) {
  const auto& g = w.geometry;
  return g.conicity > 0.0 ? 2.0 * kPi * std::sqrt(g.rolling_radius * g.contact_half_spacing / g.conicity) : 0.0;
}

// The largest step: a hundredth of the shortest kinematic period (Klingel's wavelength over
// the start speed), and never more than 10 ms.
double largest_step(const LateralEquations& e, double start_speed) {
  double step = 0.01;
  for (const WheelsetContact& w : e.wheelsets()) {
    const double wavelength = klingel_wavelength(w);
    if (wavelength > 0.0) step = std::min(step, wavelength / start_speed / kSamplesPerPeriod);
  }
  return step;
}

// The axle centre's lateral displacement of wheelset w.
double axle_lateral(const WheelsetContact& w, const Eigen::VectorXd& x) { return x[w.lateral] + w.lever * x[w.yaw]; }

// Follows the half cycles of y: a new one at every change of sign; keeps the state at each peak.
class HalfCycles {
 public:
  void add(double y, double speed, const Eigen::VectorXd& x) {
    if (y * sign_ < 0.0) close();
    if (y != 0.0) sign_ = y > 0.0 ? 1.0 : -1.0;
    if (std::abs(y) > peak_.amplitude) {
      peak_ = {speed, std::abs(y)};
      if (keep_states_) peak_state_ = x;
    }
  }
  void keep_states() { keep_states_ = true; }
  // The last, unfinished half cycle counts too: an oscillation that stops crossing zero ends there.
  void finish() { close(); }
  const std::vector<LimitCyclePoint>& peaks() const { return peaks_; }
  std::vector<LimitCyclePoint>& peaks() { return peaks_; }
  std::vector<Eigen::VectorXd>& states() { return states_; }
  double current_peak() const { return peak_.amplitude; }

 private:
  void close() {
    if (peak_.amplitude > 0.0) {
      peaks_.push_back(peak_);
      if (keep_states_) states_.push_back(peak_state_);
    }
    peak_ = {};
  }
  double sign_ = 0.0;
  bool keep_states_ = false;
  LimitCyclePoint peak_;
  Eigen::VectorXd peak_state_;
  std::vector<LimitCyclePoint> peaks_;
  std::vector<Eigen::VectorXd> states_;
};

// Integrates ẋ = f(t, x) from t = 0 until `duration` or until on_step (called after every accepted
// step with the new t and x) returns false; returns the accepted steps.
int integrate(const LateralEquations& e, const std::function<double(double)>& speed_at, double duration, double h_max,
              Eigen::VectorXd& x, const std::function<bool(double, const Eigen::VectorXd&)>& on_step) {
  const auto rhs = [&](double t, const Eigen::VectorXd& state, Eigen::VectorXd* dx) {
    e.derivative(speed_at(t), state, dx);
  };
  int steps = 0;
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
      throw NumericalError("solve_nonlinear_hunting: the integration failed at " + shortest_text(speed_at(t), 6) +
                           " m/s (step " + shortest_text(h, 6) + " s, error " + shortest_text(error, 6) + ")");
    if (error <= 1.0) {
      t += h;
      x = step.y;
      ++steps;
      if (!on_step(t, x)) break;
    }
    // The usual controller of a fifth-order pair, kept within a factor of five either way.
    h *= std::clamp(0.9 * std::pow(std::max(error, 1e-10), -0.2), 0.2, 5.0);
  }
  return steps;
}

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
void read_verdict(std::vector<LimitCyclePoint> peaks, double extinction, RampDown* r, std::size_t* branch_end) {
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
    *branch_end = last;
  }
  r->curve = std::move(peaks);
}

// The growth rate of the half-cycle amplitudes A_k over the second half of a hold, per period: the
// least-squares slope of ln A_k against k (two half cycles a period; the last, unfinished half
// cycle left out), and the most by which the peaks' errors can have moved it. The errors are not
// noise but deterministic and correlated (the peaks' sampling, in a pattern that repeats with the
// step's phase against the cycle; what is left of the settling), so no standard error describes
// them. The bound is a worst case instead: the slope is linear in the data,
// s = Σ d_k l_k / Σ d_k² (d_k = k − k̄), so an error e_k in l_k moves it by Σ d_k e_k / Σ d_k².
//  - A wobble |w_k| ≤ R, R the largest |residual| after the fit, moves it by at most
//    R·Σ|d_k| / Σd_k² (≈ 3R/n over n half cycles), whatever the wobble's pattern.
//  - The sampling: near its peak y = A·cos(ω(t − t_p)), and the accepted steps are at most h
//    apart (largest_step), so one sample lies within h/2 of t_p and the largest sampled |y| is
//    at least A·cos(ωh/2): l_k = ln A_k + e_k with −δ ≤ e_k ≤ 0, δ = −ln cos(ωh/2) ≈ (ωh)²/8.
//    A one-sided error moves the slope by at most δ·Σ_{d_k>0} d_k / Σd_k² = δ·Σ|d_k| / (2Σd_k²)
//    (Σd_k = 0, so the positive d_k sum to half of Σ|d_k|). It is added whole, not seen in R: the
//    part of the sampling pattern that correlates with k is absorbed into the slope.
// R is measured after the fit, so a slow drift that correlates with k (a settling still under
// way) is absorbed too and not bounded here: the rate over each half of the span, compared
// (hold_rate's change), shows it.
//
// The slope of ln A_k over half cycles [begin, end) and its bound (above), with δ the sampling's
// most in ln A. At least 4 half cycles; a slope of 0 with an infinite bound otherwise.
Slope fitted_slope(const std::vector<LimitCyclePoint>& peaks, std::size_t begin, std::size_t end, double delta) {
  Slope fit;
  if (end < begin + 4) return fit;
  const double n = static_cast<double>(end - begin);
  double mean_k = 0.0, mean_l = 0.0;
  for (std::size_t k = begin; k < end; ++k) mean_k += static_cast<double>(k), mean_l += std::log(peaks[k].amplitude);
  mean_k /= n, mean_l /= n;
  double skk = 0.0, skl = 0.0, sum_abs_dk = 0.0;
  for (std::size_t k = begin; k < end; ++k) {
    const double dk = static_cast<double>(k) - mean_k;
    skk += dk * dk, skl += dk * (std::log(peaks[k].amplitude) - mean_l), sum_abs_dk += std::abs(dk);
  }
  const double slope = skl / skk;
  double envelope = 0.0;
  for (std::size_t k = begin; k < end; ++k)
    envelope = std::max(envelope, std::abs(std::log(peaks[k].amplitude) - mean_l - slope * (static_cast<double>(k) - mean_k)));
  fit.per_period = 2.0 * slope;
  fit.bound = 2.0 * (envelope + 0.5 * delta) * sum_abs_dk / skk;
  return fit;
}

}  // namespace

RampDown ramp_down(const LateralEquations& e, const NonlinearHuntingOptions& o, double ramp_rate,
                   BranchStates* branch) {
  RampDown r;
  r.ramp_rate = ramp_rate;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(e.size());
  for (const WheelsetContact& w : e.wheelsets()) x[w.lateral] = o.disturbance;
  const double duration = (o.start_speed - o.end_speed) / ramp_rate;
  const auto speed_at = [&](double t) { return o.start_speed - ramp_rate * t; };
  std::vector<HalfCycles> cycles(e.wheelsets().size());
  bool unbounded = false;
  const auto watch = [&](double t, const Eigen::VectorXd& state) {
    for (std::size_t k = 0; k < cycles.size(); ++k) {
      const double y = axle_lateral(e.wheelsets()[k], state);
      cycles[k].add(y, speed_at(t), state);
      // Beyond the bound nothing physical is left to follow: stop, before the growth overflows.
      if (std::abs(y) > o.amplitude_bound) unbounded = true;
    }
    return !unbounded;
  };
  if (branch)
    for (HalfCycles& c : cycles) c.keep_states();
  watch(0.0, x);
  r.steps = integrate(e, speed_at, duration, largest_step(e, o.start_speed), x, watch);
  // The wheelset that carries the oscillation most: the largest Σ of half-cycle amplitudes.
  double most = -1.0;
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    cycles[k].finish();
    double sum = 0.0;
    for (const LimitCyclePoint& p : cycles[k].peaks()) sum += p.amplitude;
    if (sum > most) {
      most = sum;
      r.watched_wheelset = static_cast<int>(k);
    }
  }
  HalfCycles& watched = cycles[static_cast<std::size_t>(r.watched_wheelset)];
  if (unbounded) {
    r.verdict = NonlinearHuntingVerdict::unbounded_growth;
    r.curve = std::move(watched.peaks());
    return r;
  }
  std::size_t branch_end = 0;
  read_verdict(std::move(watched.peaks()), o.extinction_amplitude, &r, &branch_end);
  if (branch) {
    branch->states = std::move(watched.states());
    branch->branch_end = branch_end;
  }
  return r;
}

bool collapsing_at_end(const std::vector<LimitCyclePoint>& curve) {
  // The last point is the unfinished half cycle where the ramp stopped (HalfCycles::finish): its
  // amplitude is only as large as the motion got before the end, so the two before it are compared.
  const std::size_t n = curve.size();
  return n >= 3 && curve[n - 2].amplitude < (1.0 - kOnBranchDecay) * curve[n - 3].amplitude;
}

HoldRate hold_rate(const std::vector<LimitCyclePoint>& peaks, double delta) {
  HoldRate r;
  if (peaks.size() < 2) return r;
  const std::size_t end = peaks.size() - 1, begin = std::max<std::size_t>(1, end / 2), middle = (begin + end) / 2;
  r.rate = fitted_slope(peaks, begin, end, delta);
  const Slope early = fitted_slope(peaks, begin, middle, delta), late = fitted_slope(peaks, middle, end, delta);
  r.change = late.per_period - early.per_period;
  r.change_bound = early.bound + late.bound;
  return r;
}

double sampling_error(double omega, double h) {
  const double c = std::cos(0.5 * omega * h);
  return 0.5 * omega * h < 0.5 * kPi && c > 0.0 ? -std::log(c) : std::numeric_limits<double>::infinity();
}

RateVerdict rate_verdict(const HoldRate& r) {
  if (!std::isfinite(r.rate.bound)) return RateVerdict::undecided;
  // A change of the rate toward the threshold may yet carry it across; one away from it cannot.
  // Nor can a falling rate of an amplitude resolved to grow: near its branch a cycle's amplitude
  // follows one first-order law, dA/dt = f(A) (averaging over the cycle), so a growing amplitude
  // approaches a cycle (its rate tends to 0) or grows on; it does not turn to decay.
  const bool growing = r.rate.per_period - r.rate.bound > 0.0;
  const bool toward_threshold = (r.change > 0.0) == (r.rate.per_period < -kHoldRate) && !growing;
  if (!std::isfinite(r.change_bound) || (std::abs(r.change) > r.change_bound && toward_threshold))
    return RateVerdict::undecided;
  if (r.rate.per_period - r.rate.bound >= -kHoldRate) return RateVerdict::survives;
  if (r.rate.per_period + r.rate.bound < -kHoldRate) return RateVerdict::dies;
  return RateVerdict::undecided;
}

SpeedHold hold_speed(const LateralEquations& e, const NonlinearHuntingOptions& o, double speed,
                     const Eigen::VectorXd& start, int watched, int periods) {
  SpeedHold hold;
  hold.speed = speed;
  const WheelsetContact& w = e.wheelsets()[static_cast<std::size_t>(watched)];
  Eigen::VectorXd x = start;
  hold.start_amplitude = std::abs(axle_lateral(w, x));
  const double half = 0.5 * hold.start_amplitude;
  HalfCycles cycles;
  bool died = false;
  // The times of the first and the last zero crossing (a half cycle closing), for the cycle's ω.
  double first_crossing = 0.0, last_crossing = 0.0;
  const auto watch = [&](double t, const Eigen::VectorXd& state) {
    const double y = axle_lateral(w, state);
    const std::size_t closed = cycles.peaks().size();
    cycles.add(y, speed, state);
    const auto& p = cycles.peaks();
    if (p.size() > closed) (closed == 0 ? first_crossing : last_crossing) = t;
    // The first half cycle is the start's own; a later one below half of it: the cycle collapsed.
    if (p.size() > 1 && p.back().amplitude < half) died = true;
    if (std::abs(y) > o.amplitude_bound) return false;  // grows: it survives, and no more is needed
    return !died && static_cast<int>(p.size()) < 2 * periods + 1;
  };
  // The hunting period is at least the Klingel period of the wheelset (a bogie's is longer, by
  // up to about two): four times the Klingel time of the periods is more than enough time.
  const double wavelength = std::max(klingel_wavelength(w), 1.0), h_max = largest_step(e, speed);
  hold.steps = integrate(e, [speed](double) { return speed; }, 4.0 * periods * wavelength / speed, h_max, x, watch);
  const auto& p = cycles.peaks();
  const bool grew = std::abs(axle_lateral(w, x)) > o.amplitude_bound;
  hold.periods = static_cast<int>(p.size()) / 2;
  hold.end_amplitude = p.empty() ? std::abs(axle_lateral(w, x)) : p.back().amplitude;
  // Near the fold the collapse is slow (the cycle lingers where the branch was) and so is the
  // approach to a cycle just above it: a hold that neither fell below half the start nor grew past
  // the bound is decided by its amplitude's growth rate over its second half (hold_rate), against
  // −kHoldRate, only where two estimates agree: the rate resolved (its worst case clear of the
  // threshold), and no resolved change of the rate between the halves of that span toward the
  // threshold (a settling still under way, which could carry it across; a change away from it, a
  // collapse speeding up or a growth, cannot). Either failing, or a hold too short to fit, is
  // undecided, not surviving: the caller holds longer (the bounds fall as 1/periods) or says so.
  // The sampling's δ needs the cycle's ω: π per half cycle between the first and last crossings
  // (every closed half cycle ended at a crossing).
  const double omega = p.size() >= 2 && last_crossing > first_crossing
                           ? kPi * static_cast<double>(p.size() - 1) / (last_crossing - first_crossing)
                           : 0.0;
  const HoldRate rate = hold_rate(p, omega > 0.0 ? sampling_error(omega, h_max) : std::numeric_limits<double>::infinity());
  hold.rate_per_period = rate.rate.per_period;
  hold.rate_error = rate.rate.bound;
  hold.rate_change_per_period = rate.change;
  hold.rate_change_error = rate.change_bound;
  const bool completed = static_cast<int>(p.size()) >= 2 * periods + 1;
  if (died) {
    hold.survives = false;
  } else if (grew) {
    hold.survives = true;
  } else if (!completed) {
    hold.undecided = true;  // stopped early without dying or growing: cannot happen but by the bound
  } else {
    const RateVerdict verdict = rate_verdict(rate);
    hold.survives = verdict == RateVerdict::survives;
    hold.undecided = verdict == RateVerdict::undecided;
  }
  return hold;
}

}  // namespace railmodal::stability
