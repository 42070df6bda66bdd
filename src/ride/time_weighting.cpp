// Digital comfort weightings by the bilinear transform: derivation, choice of prewarping and
// the measured error against the analog definitions in docs/ride.md, "Ride indices in time".
#include "ride/time_weighting.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railmodal::ride {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> multiply(const std::vector<double>& p, const std::vector<double>& q) {
  std::vector<double> out(p.size() + q.size() - 1, 0.0);
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = 0; j < q.size(); ++j) out[i + j] += p[i] * q[j];
  return out;
}

// Σ_k c_k s^k with s = c(1 − z⁻¹)/(1 + z⁻¹), times (1 + z⁻¹)^order: a polynomial in z⁻¹.
std::vector<double> mapped(const std::vector<double>& coefficients, double c, size_t order) {
  std::vector<double> out(order + 1, 0.0);
  for (size_t k = 0; k < coefficients.size(); ++k) {
    std::vector<double> term{std::pow(c, static_cast<double>(k)) * coefficients[k]};
    for (size_t i = 0; i < k; ++i) term = multiply(term, {1.0, -1.0});
    for (size_t i = k; i < order; ++i) term = multiply(term, {1.0, 1.0});
    for (size_t i = 0; i < term.size(); ++i) out[i] += term[i];
  }
  return out;
}

}  // namespace

DigitalFilter::Section bilinear(const std::vector<double>& numerator, const std::vector<double>& denominator,
                                double time_step, double prewarp_hz) {
  const double wp = 2.0 * kPi * prewarp_hz;
  if (prewarp_hz > 0.0 && !(wp * time_step / 2.0 < kPi / 2.0))
    throw std::invalid_argument("bilinear transform: the prewarping frequency must be below the Nyquist frequency");
  const double c = prewarp_hz > 0.0 ? wp / std::tan(wp * time_step / 2.0) : 2.0 / time_step;
  const size_t order = std::max(numerator.size(), denominator.size()) - 1;
  DigitalFilter::Section section{mapped(numerator, c, order), mapped(denominator, c, order)};
  const double a0 = section.a[0];
  for (double& b : section.b) b /= a0;
  for (double& a : section.a) a /= a0;
  return section;
}

namespace {

// The cascade in one pass over the samples, every section of order ≤ 3 padded with zero
// coefficients: each sample goes through all sections while their states are in registers,
// and the sections' recursions overlap (section j at sample n beside section j + 1 at sample
// n − 1) where one pass a section waits on each sample's recursion in turn. The same
// operations in the same order as the generic loop below (a padded state is 0·x − 0·y + 0,
// exactly +0, and adding it changes nothing), so the same samples bit for bit.
constexpr size_t kFusedOrder = 3;

struct PaddedSection {
  double b[kFusedOrder + 1] = {}, a[kFusedOrder + 1] = {};
};

// In place when `in` == `out` (each sample is read before it is written).
void apply_fused(const std::vector<PaddedSection>& sections, const double* in, double* out, Eigen::Index n,
                 std::vector<double>* state) {
  const size_t count = sections.size();
  state->resize(kFusedOrder * count, 0.0);
  for (Eigen::Index i = 0; i < n; ++i) {
    double x = in[i];
    for (size_t j = 0; j < count; ++j) {
      const PaddedSection& s = sections[j];
      double* z = &(*state)[kFusedOrder * j];
      const double y = s.b[0] * x + z[0];
      z[0] = s.b[1] * x - s.a[1] * y + z[1];
      z[1] = s.b[2] * x - s.a[2] * y + z[2];
      z[2] = s.b[3] * x - s.a[3] * y + 0.0;
      x = y;
    }
    out[i] = x;
  }
}

// The sections padded for apply_fused; fewer than the filter's when one is of higher order.
std::vector<PaddedSection> padded(const std::vector<DigitalFilter::Section>& sections) {
  std::vector<PaddedSection> out;
  for (const DigitalFilter::Section& s : sections) {
    if (s.a.size() > kFusedOrder + 1 || s.b.size() > s.a.size()) break;
    out.emplace_back();
    for (size_t k = 0; k < s.a.size(); ++k) out.back().a[k] = s.a[k];
    for (size_t k = 0; k < s.b.size(); ++k) out.back().b[k] = s.b[k];
  }
  return out;
}

// Two padded cascades side by side, lane 0 and lane 1 of a two-double vector, each lane the
// same operations in the same order as apply_fused on its own (the vector operations are
// lane-wise IEEE operations). The shorter cascade is padded with identity sections
// (b = 1, 0, 0, 0; a = 1, 0, 0, 0), which pass each sample through unchanged: y = 1·x + 0 with
// a state that stays exactly 0. kSections > 0 fixes the section count, so that the states are
// locals the compiler keeps in registers; 0: any count.
#if defined(__GNUC__) || defined(__clang__)
typedef double Lanes __attribute__((vector_size(2 * sizeof(double))));
#else
struct Lanes {
  double v[2];
  double operator[](int l) const { return v[l]; }
};
inline Lanes operator*(Lanes p, Lanes q) { return {{p.v[0] * q.v[0], p.v[1] * q.v[1]}}; }
inline Lanes operator+(Lanes p, Lanes q) { return {{p.v[0] + q.v[0], p.v[1] + q.v[1]}}; }
inline Lanes operator-(Lanes p, Lanes q) { return {{p.v[0] - q.v[0], p.v[1] - q.v[1]}}; }
#endif

struct SectionPair {
  Lanes b[kFusedOrder + 1], a[kFusedOrder + 1];
};

template <int kSections>
void apply_fused_pair(const std::vector<SectionPair>& sections, const double* in0, const double* in1, Eigen::Index n,
                      double* out0, double* out1, std::vector<Lanes>* state) {
  constexpr bool fixed = kSections > 0;
  const int count = fixed ? kSections : static_cast<int>(sections.size());
  state->resize(kFusedOrder * sections.size(), Lanes{0.0, 0.0});
  Lanes local[fixed ? kFusedOrder * kSections : 1];
  Lanes* z = fixed ? local : state->data();
  if (fixed) std::copy(state->begin(), state->end(), local);
  const SectionPair* s = sections.data();
  const Lanes zero{0.0, 0.0};
  for (Eigen::Index i = 0; i < n; ++i) {
    Lanes x{in0[i], in1[i]};
    for (int j = 0; j < count; ++j) {
      Lanes* zj = z + kFusedOrder * j;
      const Lanes y = s[j].b[0] * x + zj[0];
      zj[0] = s[j].b[1] * x - s[j].a[1] * y + zj[1];
      zj[1] = s[j].b[2] * x - s[j].a[2] * y + zj[2];
      zj[2] = s[j].b[3] * x - s[j].a[3] * y + zero;
      x = y;
    }
    out0[i] = x[0];
    out1[i] = x[1];
  }
  if (fixed) std::copy(local, local + kFusedOrder * kSections, state->begin());
}

// The two cascades as lanes; empty when either has a section of order above kFusedOrder.
std::vector<SectionPair> paired(const std::vector<DigitalFilter::Section>& first,
                                const std::vector<DigitalFilter::Section>& second) {
  const std::vector<PaddedSection> p0 = padded(first), p1 = padded(second);
  if (p0.size() != first.size() || p1.size() != second.size()) return {};
  PaddedSection identity;
  identity.b[0] = identity.a[0] = 1.0;
  std::vector<SectionPair> out(std::max(p0.size(), p1.size()));
  for (size_t j = 0; j < out.size(); ++j) {
    const PaddedSection& s0 = j < p0.size() ? p0[j] : identity;
    const PaddedSection& s1 = j < p1.size() ? p1[j] : identity;
    for (size_t k = 0; k <= kFusedOrder; ++k) out[j].b[k] = Lanes{s0.b[k], s1.b[k]}, out[j].a[k] = Lanes{s0.a[k], s1.a[k]};
  }
  return out;
}

void run_pair(const std::vector<SectionPair>& sections, const double* in0, const double* in1, Eigen::Index n,
              double* out0, double* out1, std::vector<Lanes>* state) {
  switch (sections.size()) {
    case 1: return apply_fused_pair<1>(sections, in0, in1, n, out0, out1, state);
    case 2: return apply_fused_pair<2>(sections, in0, in1, n, out0, out1, state);
    case 3: return apply_fused_pair<3>(sections, in0, in1, n, out0, out1, state);
    case 4: return apply_fused_pair<4>(sections, in0, in1, n, out0, out1, state);
    default: return apply_fused_pair<0>(sections, in0, in1, n, out0, out1, state);
  }
}

// One section of a pair on one sample, its order fixed (1 … kFusedOrder): the operations of
// apply_fused_pair's padded section without the padding, which for a finite sample is exactly
// +0 (0·x − 0·y + 0 is +0 whatever the signs of x and y) and adds nothing.
template <int kOrder>
inline Lanes section_step(const SectionPair& s, Lanes* z, Lanes x) {
  const Lanes zero{0.0, 0.0};
  const Lanes y = s.b[0] * x + z[0];
  if (kOrder == 1) {
    z[0] = s.b[1] * x - s.a[1] * y + zero;
  } else if (kOrder == 2) {
    z[0] = s.b[1] * x - s.a[1] * y + z[1];
    z[1] = s.b[2] * x - s.a[2] * y + zero;
  } else {
    z[0] = s.b[1] * x - s.a[1] * y + z[1];
    z[1] = s.b[2] * x - s.a[2] * y + z[2];
    z[2] = s.b[3] * x - s.a[3] * y + zero;
  }
  return y;
}

// Two histories a and b through two cascades each, in one loop: the first cascade with a in
// lane 0 and b in lane 1, the second likewise. Four recursions in flight instead of two, so
// the processor overlaps them where a pair alone waits on its sections' recursions. The
// section counts and orders fixed, so that the states are locals kept in registers.
template <int kSections0, int kOrder0, int kSections1, int kOrder1>
void apply_quad(const SectionPair* first, const SectionPair* second, const double* a, const double* b, Eigen::Index n,
                double* first_a, double* first_b, double* second_a, double* second_b, std::vector<Lanes>* first_state,
                std::vector<Lanes>* second_state) {
  Lanes z0[kFusedOrder * kSections0], z1[kFusedOrder * kSections1];
  std::copy(first_state->begin(), first_state->end(), z0);
  std::copy(second_state->begin(), second_state->end(), z1);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Lanes x{a[i], b[i]};
    Lanes y0 = x, y1 = x;
    for (int j = 0; j < kSections0; ++j) y0 = section_step<kOrder0>(first[j], z0 + kFusedOrder * j, y0);
    for (int j = 0; j < kSections1; ++j) y1 = section_step<kOrder1>(second[j], z1 + kFusedOrder * j, y1);
    first_a[i] = y0[0];
    first_b[i] = y0[1];
    second_a[i] = y1[0];
    second_b[i] = y1[1];
  }
  std::copy(z0, z0 + kFusedOrder * kSections0, first_state->begin());
  std::copy(z1, z1 + kFusedOrder * kSections1, second_state->begin());
}

// The highest order of a cascade's sections.
size_t cascade_order(const std::vector<DigitalFilter::Section>& sections) {
  size_t order = 0;
  for (const DigitalFilter::Section& s : sections) order = std::max(order, s.a.size() - 1);
  return order;
}

// The two histories' passes: apply_quad where it is instantiated (EN 12299's four sections of
// order 2 beside Sperling's one of order 3), else each cascade's pair over a and b in turn.
// `first` and `second` are each cascade paired with itself; the states are theirs.
void run_quad(const std::vector<SectionPair>& first, size_t first_order, const std::vector<SectionPair>& second,
              size_t second_order, const double* a, const double* b, Eigen::Index n, double* first_a,
              double* first_b, double* second_a, double* second_b, std::vector<Lanes>* first_state,
              std::vector<Lanes>* second_state) {
  first_state->resize(kFusedOrder * first.size(), Lanes{0.0, 0.0});
  second_state->resize(kFusedOrder * second.size(), Lanes{0.0, 0.0});
  if (first_order == 2 && second.size() == 1 && second_order == 3) {
    if (first.size() == 4)  // Wb (vertical) beside Sperling's B
      return apply_quad<4, 2, 1, 3>(first.data(), second.data(), a, b, n, first_a, first_b, second_a, second_b,
                                    first_state, second_state);
    if (first.size() == 3)  // Wd (lateral), without the upward step, beside Sperling's B
      return apply_quad<3, 2, 1, 3>(first.data(), second.data(), a, b, n, first_a, first_b, second_a, second_b,
                                    first_state, second_state);
  }
  run_pair(first, a, b, n, first_a, first_b, first_state);
  run_pair(second, a, b, n, second_a, second_b, second_state);
}

// The first `from` samples of a run whose output is not kept: run through `run` in chunks
// of at most `buffer` samples, written there and overwritten, so that the state they leave is
// the whole run's (the same operations in the same order) without a buffer of `from` samples.
template <class Run>
void run_discarded(Eigen::Index from, Eigen::Index buffer, Run run) {
  for (Eigen::Index done = 0; done < from && buffer > 0; done += std::min(buffer, from - done))
    run(done, std::min(buffer, from - done));
}

}  // namespace

void DigitalFilter::apply_from(const DigitalFilter& first, const DigitalFilter& second,
                               Eigen::Ref<const Eigen::VectorXd> input, Eigen::Index from, Eigen::VectorXd* first_out,
                               Eigen::VectorXd* second_out) {
  const std::vector<SectionPair> sections = paired(first.sections_, second.sections_);
  if (sections.empty()) {
    *first_out = first.apply_from(input, from);
    *second_out = second.apply_from(input, from);
    return;
  }
  const Eigen::Index kept = input.size() - from;
  first_out->resize(kept);
  second_out->resize(kept);
  std::vector<Lanes> state;
  const double* in = input.data();
  run_discarded(from, kept, [&](Eigen::Index start, Eigen::Index n) {
    run_pair(sections, in + start, in + start, n, first_out->data(), second_out->data(), &state);
  });
  run_pair(sections, in + from, in + from, kept, first_out->data(), second_out->data(), &state);
}

void DigitalFilter::apply_second_pass(const DigitalFilter& first, const DigitalFilter& second,
                                      Eigen::Ref<const Eigen::VectorXd> period, Eigen::VectorXd* first_out,
                                      Eigen::VectorXd* second_out) {
  const std::vector<SectionPair> sections = paired(first.sections_, second.sections_);
  if (sections.empty()) {
    *first_out = first.apply_second_pass(period);
    *second_out = second.apply_second_pass(period);
    return;
  }
  // Each lane's first pass over its own lead-in (as apply_second_pass); the shorter lead-in
  // preceded by zeros, through which a cascade at rest stays exactly at rest.
  const Eigen::Index n = period.size();
  const Eigen::Index lead0 = std::min<Eigen::Index>(n, first.lead_in());
  const Eigen::Index lead1 = std::min<Eigen::Index>(n, second.lead_in());
  const Eigen::Index lead = std::max(lead0, lead1);
  Eigen::VectorXd in0 = period.tail(lead), in1 = period.tail(lead);
  in0.head(lead - lead0).setZero();
  in1.head(lead - lead1).setZero();
  first_out->resize(n);
  second_out->resize(n);
  std::vector<Lanes> state;
  run_pair(sections, in0.data(), in1.data(), lead, first_out->data(), second_out->data(), &state);  // first pass
  run_pair(sections, period.data(), period.data(), n, first_out->data(), second_out->data(), &state);
}

void DigitalFilter::apply_from(const DigitalFilter& first, const DigitalFilter& second, Eigen::Ref<const Eigen::VectorXd> a,
                               Eigen::Ref<const Eigen::VectorXd> b, Eigen::Index from, Eigen::VectorXd* first_a,
                               Eigen::VectorXd* second_a, Eigen::VectorXd* first_b, Eigen::VectorXd* second_b) {
  const std::vector<SectionPair> ff = paired(first.sections_, first.sections_);
  const std::vector<SectionPair> ss = paired(second.sections_, second.sections_);
  if (ff.empty() || ss.empty() || a.size() != b.size()) {
    apply_from(first, second, a, from, first_a, second_a);
    apply_from(first, second, b, from, first_b, second_b);
    return;
  }
  const Eigen::Index kept = a.size() - from;
  for (Eigen::VectorXd* out : {first_a, second_a, first_b, second_b}) out->resize(kept);
  const size_t first_order = cascade_order(first.sections_), second_order = cascade_order(second.sections_);
  std::vector<Lanes> first_state, second_state;
  const auto run = [&](Eigen::Index start, Eigen::Index n) {
    run_quad(ff, first_order, ss, second_order, a.data() + start, b.data() + start, n, first_a->data(),
             first_b->data(), second_a->data(), second_b->data(), &first_state, &second_state);
  };
  run_discarded(from, kept, run);
  run(from, kept);
}

void DigitalFilter::apply_second_pass(const DigitalFilter& first, const DigitalFilter& second,
                                      Eigen::Ref<const Eigen::VectorXd> a, Eigen::Ref<const Eigen::VectorXd> b,
                                      Eigen::VectorXd* first_a, Eigen::VectorXd* second_a, Eigen::VectorXd* first_b,
                                      Eigen::VectorXd* second_b) {
  const std::vector<SectionPair> ff = paired(first.sections_, first.sections_);
  const std::vector<SectionPair> ss = paired(second.sections_, second.sections_);
  if (ff.empty() || ss.empty() || a.size() != b.size()) {
    apply_second_pass(first, second, a, first_a, second_a);
    apply_second_pass(first, second, b, first_b, second_b);
    return;
  }
  const Eigen::Index n = a.size();
  for (Eigen::VectorXd* out : {first_a, second_a, first_b, second_b}) out->resize(n);
  // Each cascade's first pass over its own lead-in, a and b side by side (as the pair's lanes
  // do, from rest), then the period through both cascades at once.
  const Eigen::Index lead0 = std::min<Eigen::Index>(n, first.lead_in());
  const Eigen::Index lead1 = std::min<Eigen::Index>(n, second.lead_in());
  std::vector<Lanes> first_state, second_state;
  run_pair(ff, a.data() + n - lead0, b.data() + n - lead0, lead0, first_a->data(), first_b->data(), &first_state);
  run_pair(ss, a.data() + n - lead1, b.data() + n - lead1, lead1, second_a->data(), second_b->data(), &second_state);
  run_quad(ff, cascade_order(first.sections_), ss, cascade_order(second.sections_), a.data(), b.data(), n,
           first_a->data(), first_b->data(), second_a->data(), second_b->data(), &first_state, &second_state);
}

Eigen::VectorXd DigitalFilter::apply(Eigen::Ref<const Eigen::VectorXd> input) const { return apply_from(input, 0); }

Eigen::VectorXd DigitalFilter::apply_from(Eigen::Ref<const Eigen::VectorXd> input, Eigen::Index from) const {
  const Eigen::Index kept = input.size() - from;
  const std::vector<PaddedSection> fused = padded(sections_);
  if (fused.size() == sections_.size()) {
    Eigen::VectorXd out(kept);
    std::vector<double> state;
    run_discarded(from, kept, [&](Eigen::Index start, Eigen::Index n) {
      apply_fused(fused, input.data() + start, out.data(), n, &state);
    });
    apply_fused(fused, input.data() + from, out.data(), kept, &state);
    return out;
  }
  Eigen::VectorXd signal = input;
  for (const Section& s : sections_) {
    const size_t order = s.a.size() - 1;
    std::vector<double> state(order + 1, 0.0);  // transposed direct form II: state[order] stays 0
    for (Eigen::Index n = 0; n < signal.size(); ++n) {
      const double x = signal(n);
      const double y = s.b[0] * x + state[0];
      for (size_t k = 0; k < order; ++k) state[k] = s.b[k + 1] * x - s.a[k + 1] * y + state[k + 1];
      signal(n) = y;
    }
  }
  if (from == 0) return signal;
  return signal.tail(kept);
}

long DigitalFilter::lead_in() const {
  // The slowest pole: the largest root modulus of z^order + a₁z^(order−1) + … + a_order over
  // the sections (their companion matrices' eigenvalues).
  double slowest = 0.0;
  for (const Section& s : sections_) {
    const Eigen::Index order = static_cast<Eigen::Index>(s.a.size()) - 1;
    if (order < 1) continue;
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(order, order);
    for (Eigen::Index k = 0; k < order; ++k) companion(0, k) = -s.a[static_cast<size_t>(k + 1)];
    for (Eigen::Index k = 1; k < order; ++k) companion(k, k - 1) = 1.0;
    slowest = std::max(slowest, companion.eigenvalues().cwiseAbs().maxCoeff());
  }
  if (!(slowest < 1.0)) return std::numeric_limits<long>::max();  // never decays: no lead-in is enough
  if (slowest == 0.0) return 0;
  return static_cast<long>(std::ceil(std::log(kLeadInDecay) / std::log(slowest)));
}

Eigen::VectorXd DigitalFilter::apply_second_pass(Eigen::Ref<const Eigen::VectorXd> period) const {
  const std::vector<PaddedSection> fused = padded(sections_);
  if (fused.size() != sections_.size()) {
    Eigen::VectorXd twice(2 * period.size());
    twice << period, period;
    return apply_from(twice, period.size());
  }
  // The first pass over the period's last lead_in() samples only when that is shorter than the
  // period: the state it leaves differs from the whole pass's by the response to the earlier
  // samples, decayed by the slowest pole's |p|^lead_in ≤ kLeadInDecay (bound: time_weighting.hpp).
  const Eigen::Index lead = std::min<Eigen::Index>(period.size(), lead_in());
  Eigen::VectorXd signal = period.tail(lead);
  std::vector<double> state;
  apply_fused(fused, signal.data(), signal.data(), lead, &state);  // the first pass: only its final state is kept
  signal.resize(period.size());
  apply_fused(fused, period.data(), signal.data(), period.size(), &state);
  return signal;
}

std::complex<double> DigitalFilter::response(double frequency, double time_step) const {
  const std::complex<double> zinv = std::polar(1.0, -2.0 * kPi * frequency * time_step);
  std::complex<double> h = 1.0;
  for (const Section& s : sections_) {
    std::complex<double> num = 0.0, den = 0.0, power = 1.0;
    for (size_t k = 0; k < s.a.size(); ++k, power *= zinv) {
      num += s.b[k] * power;
      den += s.a[k] * power;
    }
    h *= num / den;
  }
  return h;
}

// The four factors of W (comfort_weighting.hpp), each a section prewarped at its own corner,
// so the band limits, the a–v transition and the step sit at their analog frequencies. The
// low-pass band limit (f2 = 100 Hz) is prewarped at the lower of f2 and 0.45/Δt, below the
// Nyquist frequency: at the ride's usual rates its corner is at or above Nyquist, where the
// analog filter is near 1 over the band that matters, and the mapped section keeps that.
DigitalFilter digital_weighting(const FrequencyWeighting& w, double time_step) {
  const double w1 = 2.0 * kPi * w.f1, w2 = 2.0 * kPi * w.f2, w3 = 2.0 * kPi * w.f3, w4 = 2.0 * kPi * w.f4;
  const double nyquist_margin = 0.45 / time_step;
  std::vector<DigitalFilter::Section> sections;
  sections.push_back(bilinear({0.0, 0.0, 1.0}, {w1 * w1, w1 / w.q1, 1.0}, time_step, w.f1));
  sections.push_back(bilinear({w2 * w2}, {w2 * w2, w2 / w.q2, 1.0}, time_step, std::min(w.f2, nyquist_margin)));
  sections.push_back(
      bilinear({w.gain, w.gain / w3}, {1.0, 1.0 / (w.q4 * w4), 1.0 / (w4 * w4)}, time_step, std::min(w.f4, nyquist_margin)));
  if (w.has_upward_step) {
    const double w5 = 2.0 * kPi * w.f5, w6 = 2.0 * kPi * w.f6;
    sections.push_back(bilinear({1.0, 1.0 / (w.q5 * w5), 1.0 / (w5 * w5)}, {1.0, 1.0 / (w.q6 * w6), 1.0 / (w6 * w6)},
                                time_step, std::min(std::sqrt(w.f5 * w.f6), nyquist_margin)));
  }
  return DigitalFilter(std::move(sections));
}

// B_v(f) = 0.588 |N(jf)/D(jf)| with N(p) = √1.911 p + 0.25 p², D(p) = 1 + 1.563 p + 0.277 p² +
// 0.0368 p³ (p = s/2π, f in Hz): |N(jf)|² = 1.911 f² + (0.25 f²)² and D(jf) = (1 − 0.277 f²) +
// j(1.563 f − 0.0368 f³), the magnitude Sperling's formula gives (comfort_weighting.cpp), and D
// is Hurwitz (all coefficients positive, 0.277·1.563 > 0.0368·1), so the filter is stable.
// Prewarped at 5 Hz, near the top of B.
DigitalFilter digital_sperling(SperlingDirection direction, double time_step) {
  const double gain = 0.588 * (direction == SperlingDirection::vertical ? 1.0 : 1.25);
  const double p = 1.0 / (2.0 * kPi);  // p = s/(2π)
  const std::vector<double> numerator{0.0, gain * std::sqrt(1.911) * p, gain * 0.25 * p * p};
  const std::vector<double> denominator{1.0, 1.563 * p, 0.277 * p * p, 0.0368 * p * p * p};
  return DigitalFilter({bilinear(numerator, denominator, time_step, std::min(5.0, 0.45 / time_step))});
}

}  // namespace railmodal::ride
