// The ride march of ride_march.hpp in modal coordinates: the same exact discretisation (the
// first-order holds chained at each wheel's kink phase δ), with the state s = V z on the
// eigenvectors of A, so that Φ(h) is diagonal and a step costs O(modes · inputs) instead of
// dense 2n × 2n and 2n × 3 products. Two further savings, both exact:
//  * the inputs standing at one track position (the two axleboxes of an axle) see the same
//    track at the same time, so their loads are summed once, into one input per profile;
//  * a conjugate pair of modes is marched once (the state is real: z_k̄ = conj(z_k)).
// Method and the choice of path: docs/ride.md, "The vehicle over the track".
#pragma once

#include <Eigen/Core>
#include <complex>
#include <memory>
#include <vector>

#include "ride/ride_state_space.hpp"
#include "ride/track_under_wheels.hpp"

namespace railmodal::ride {

/// The largest 2-norm condition number of the eigenvector matrix (unit columns) of A balanced
/// (A = D Â D⁻¹, D a diagonal of powers of 2) for which the modal march is used: its round-off is at most about κ·ε relative to the dense march's
/// (ε = 2.2e-16, so 2e-10 at this bound). A defective A (a repeated root with one eigenvector,
/// e.g. a critically damped motion) has κ of order 1/√ε ≈ 1e8 or infinite and goes to the
/// dense march; repeated roots with independent eigenvectors (identical uncoupled
/// subsystems) stay well conditioned and march modally.
constexpr double kModalConditionLimit = 1e6;

class ModalRideMarch {
 public:
  /// The modal march, or null when A's eigenvectors fail the condition test above (then the
  /// dense RideMarch). Arguments as RideMarch's, and the output rows to evaluate.
  static std::unique_ptr<ModalRideMarch> make(const RideStateSpace& model, const TrackUnderWheels& track,
                                              const std::vector<OutputRow>& rows, double speed, double step,
                                              double start);
  /// κ₂ of the eigenvector matrix this march was built on.
  double condition() const { return condition_; }

  /// The modal state: the real and imaginary parts of one mode of each conjugate pair and of
  /// each real mode.
  struct State {
    std::vector<double> re, im;
  };
  State rest() const;
  /// From rest, one period of `period` steps gives z_P; the periodic orbit starts at
  /// z* = z_P / (1 − μ^period) mode by mode (μ = e^{λh}). False, and `start` at rest, when a
  /// mode is (almost) undamped: min |1 − μ^period| < 1e-10 · max |1 − μ^period|, the test the
  /// dense path applies to I − Φ^period as its reciprocal condition.
  bool periodic_start(long period, State* start);
  /// The outputs at steps 0 … count − 1 from `start` at step 0, one vector each (each
  /// output's samples are summed in place there: no matrix of all outputs to copy them out of).
  std::vector<Eigen::VectorXd> outputs(State start, long count);

 private:
  ModalRideMarch() = default;
  class Cursor;  // where one input stands, step by step
  std::vector<Cursor> cursors() const;  // one an input, at step 0
  // s ← s + sign·Q₂u: between z and w.
  void shift(State* s, const std::vector<double>& now, double sign) const;
  // The march over a block of steps (ride_modal_march.cpp, "Blocks"): the inputs of each step
  // read first into `block`, then w advanced step by step, each step's w kept when asked.
  struct Block;
  void read_block(std::vector<Cursor>* cursors, long steps, Block* block, bool slopes) const;
  void advance_block(Block* block, long steps, State* w, bool keep) const;

  double speed_ = 0.0, h_ = 0.0;
  double condition_ = 0.0;
  int modes_ = 0;
  std::vector<double> mu_re_, mu_im_;         // e^{λh} per marched mode
  std::vector<std::complex<double>> lambda_;  // λ per marched mode
  // (position, profile) pairs, the inputs of the march: each reads one profile of the track
  // at one position. At step k (m steps a sample, h = Δx/(mV)) it stands at sample
  // base + phase + k/m, counted exactly (an integer and a fraction), so a wheel on a sample is
  // exactly on it; δ is the kink phase in the step, `reach` = δ·V/Δx the samples it covers.
  struct Input {
    const Eigen::VectorXd* profile = nullptr;
    Eigen::Index base = 0;
    double phase = 0.0, delta = 0.0, reach = 0.0;
  };
  std::vector<Input> inputs_;
  long per_sample_ = 1;  // m
  double step_ = 0.0;    // Δx
  bool periodic_ = false;
  // per input, the taps of w's step: Q₀ + μQ₂ on u(t), then (only where δ ≠ 0) Q₁ on
  // u(t + δ), each `modes_` coefficients, re and im
  std::vector<double> q_re_, q_im_;
  // Q₂, the end-of-step tap, per input `modes_` coefficients (z = w + Q₂u)
  std::vector<double> end_re_, end_im_;
  // outputs: y_j = Σ_k (cr·Re w − ci·Im w) + Σ_inputs (lw·u + V·ld·u'), lw including Q₂'s part
  int outputs_ = 0;
  std::vector<double> c_re_, c_im_, lw_, ld_;
  // per input, whether any output has a nonzero ld on it (a damper from the track straight into
  // the output): only those inputs' slopes are read
  std::vector<char> slope_used_;
  // The taps in the order advance_block() applies them (per input u(t), then u(t + δ) where δ ≠ 0):
  // which input each reads, and whether at t + δ.
  std::vector<int> tap_input_;
  std::vector<char> tap_mid_;
};

}  // namespace railmodal::ride
