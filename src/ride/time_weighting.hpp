// The comfort weightings of comfort_weighting.hpp as digital filters for sampled histories:
// each analog factor mapped by the bilinear transform, prewarped at the factor's own corner
// so that the corner lands where the analog one is (docs/ride.md, "Ride indices in time").
#pragma once

#include <Eigen/Core>
#include <complex>
#include <vector>

#include "railmodal/comfort_weighting.hpp"

namespace railmodal::ride {

/// A cascade of sections b(z⁻¹)/a(z⁻¹), a[0] = 1, run in transposed direct form II.
class DigitalFilter {
 public:
  struct Section {
    std::vector<double> b, a;  // coefficients of z⁰, z⁻¹, …; a[0] = 1
  };
  explicit DigitalFilter(std::vector<Section> sections) : sections_(std::move(sections)) {}
  /// The filtered samples, starting from rest. The inputs are taken by Eigen::Ref, so that a
  /// column of a matrix or a segment of a vector is read in place, not copied.
  Eigen::VectorXd apply(Eigen::Ref<const Eigen::VectorXd> input) const;
  /// apply(input).tail(input.size() − from), bit for bit, without a buffer for the first `from`
  /// samples' output (a settling run whose filtered samples are not kept).
  Eigen::VectorXd apply_from(Eigen::Ref<const Eigen::VectorXd> input, Eigen::Index from) const;
  /// The periodic steady state's samples over `period`: the second pass of a run from rest over
  /// the period's last lead_in() samples and then the period (the whole period first when it is
  /// no longer than lead_in(): apply(period, period)'s second half, bit for bit). Against the
  /// exact periodic response, each sample differs by at most 2·max|x|·Σ_{k ≥ L}|h_k| (h the
  /// impulse response, L = lead_in()), below 1e-16·max|x|·Σ|h_k| for EN 12299's and Sperling's
  /// weightings (test TimeWeighting.LeadInLeavesLessThanTheStatedTailOfTheImpulseResponse).
  Eigen::VectorXd apply_second_pass(Eigen::Ref<const Eigen::VectorXd> period) const;
  /// The samples after which the slowest pole p has decayed below kLeadInDecay: the least L
  /// with |p|^L ≤ kLeadInDecay (the largest long when a pole is on or outside the unit circle).
  long lead_in() const;
  /// 1e-20: a margin of 1e4 over the 1e-16 stated for the tail, for the residues and the
  /// cascade's near-coincident poles (a double pole's tail goes as L·|p|^L).
  static constexpr double kLeadInDecay = 1e-20;
  /// Two cascades over the same samples side by side (each sample through both while their
  /// states are in registers): *first_out = first.apply_from(input, from) and *second_out
  /// likewise, bit for bit, written into the caller's vectors (resized; one already of the size is reused,
  /// so a caller filtering several histories needs no new buffer for each). The outputs must
  /// not overlap `input`.
  static void apply_from(const DigitalFilter& first, const DigitalFilter& second,
                         Eigen::Ref<const Eigen::VectorXd> input, Eigen::Index from, Eigen::VectorXd* first_out,
                         Eigen::VectorXd* second_out);
  /// *first_out = first.apply_second_pass(period) and *second_out likewise, bit for bit, side by
  /// side as apply_from's pair (resized, reused as there; not overlapping `period`).
  static void apply_second_pass(const DigitalFilter& first, const DigitalFilter& second,
                                Eigen::Ref<const Eigen::VectorXd> period, Eigen::VectorXd* first_out,
                                Eigen::VectorXd* second_out);
  /// Two histories of one length through the same two cascades at once (four recursions in
  /// flight): the pair apply_from over `a` into *first_a, *second_a and over `b` into *first_b,
  /// *second_b, bit for bit (resized, reused as there; none overlapping `a` or `b`).
  static void apply_from(const DigitalFilter& first, const DigitalFilter& second, Eigen::Ref<const Eigen::VectorXd> a,
                         Eigen::Ref<const Eigen::VectorXd> b, Eigen::Index from, Eigen::VectorXd* first_a,
                         Eigen::VectorXd* second_a, Eigen::VectorXd* first_b, Eigen::VectorXd* second_b);
  /// The same for the pair apply_second_pass over two periods `a` and `b` of one length.
  static void apply_second_pass(const DigitalFilter& first, const DigitalFilter& second,
                                Eigen::Ref<const Eigen::VectorXd> a, Eigen::Ref<const Eigen::VectorXd> b,
                                Eigen::VectorXd* first_a, Eigen::VectorXd* second_a, Eigen::VectorXd* first_b,
                                Eigen::VectorXd* second_b);
  /// H(e^{iωΔt}) at `frequency` Hz for the sample step `time_step` s.
  std::complex<double> response(double frequency, double time_step) const;

 private:
  std::vector<Section> sections_;
};

/// One analog section N(s)/D(s) (coefficients of s⁰, s¹, …, order ≤ 3) mapped by
/// s = c(1 − z⁻¹)/(1 + z⁻¹), c = ω_p / tan(ω_p Δt/2) (prewarped at ω_p = 2π·prewarp_hz, which
/// must be below the Nyquist frequency), or c = 2/Δt for prewarp_hz = 0.
DigitalFilter::Section bilinear(const std::vector<double>& numerator, const std::vector<double>& denominator,
                                double time_step, double prewarp_hz);

/// W of EN 12299 / ISO 2631 (Wb, Wd) as four sections at step `time_step` s.
DigitalFilter digital_weighting(const FrequencyWeighting& weighting, double time_step);
/// Sperling's B(f) (comfort_weighting.hpp) as one third-order section.
DigitalFilter digital_sperling(SperlingDirection direction, double time_step);

}  // namespace railmodal::ride
