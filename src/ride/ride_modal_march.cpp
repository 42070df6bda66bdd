#include "ride/ride_modal_march.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <utility>
#include <cmath>

namespace railmodal::ride {
namespace {

using Complex = std::complex<double>;

// φ1(x) = (e^x − 1)/x and φ2(x) = (e^x − 1 − x)/x², the first-order hold's integrals of one
// mode: over a span τ with the input linear from u0 to u1, ζ(τ) = e^{λτ}ζ(0) + τφ1(λτ)β u0 +
// τφ2(λτ)β (u1 − u0) — Van Loan's G0 and G1 (ride_march.cpp) for a 1 × 1 A. Below |x| = 1
// the direct forms lose digits to cancellation, so there their Taylor series Σ x^k/(k+1)! and
// Σ x^k/(k+2)! (30 terms: the remainder is below 1/31! ≈ 1e-34).
void phi(Complex x, Complex* phi1, Complex* phi2) {
  if (std::abs(x) < 1.0) {
    Complex t1 = 1.0, t2 = 0.5;
    *phi1 = *phi2 = 0.0;
    for (int k = 0; k < 30; ++k) {
      *phi1 += t1;
      *phi2 += t2;
      t1 *= x / static_cast<double>(k + 2);
      t2 *= x / static_cast<double>(k + 3);
    }
    return;
  }
  const Complex e = std::exp(x);
  *phi1 = (e - 1.0) / x;
  *phi2 = (e - 1.0 - x) / (x * x);
}

// The three taps of one mode for an input whose kinks fall δ into each step (ride_march.cpp's
// chained holds, per mode): the factors of u(t), u(t + δ), u(t + h).
void taps(Complex lambda, double h, double delta, Complex out[3]) {
  Complex p1, p2;
  if (delta == 0.0) {
    phi(lambda * h, &p1, &p2);
    out[0] = h * (p1 - p2);
    out[1] = 0.0;
    out[2] = h * p2;
    return;
  }
  const double rest = h - delta;
  Complex r1, r2;
  phi(lambda * delta, &p1, &p2);
  phi(lambda * rest, &r1, &r2);
  const Complex carry = std::exp(lambda * rest);  // Φ(h − δ)
  out[0] = carry * delta * (p1 - p2);
  out[1] = carry * delta * p2 + rest * (r1 - r2);
  out[2] = rest * r2;
}

// Diagonal scaling by powers of 2 that brings each row and column of A to comparable size
// (Parlett and Reinsch, "Balancing a matrix for calculation of eigenvalues and eigenvectors",
// Numer. Math. 13, 1969; LAPACK's dgebal without the permutations): A = D Â D⁻¹ exactly, and
// the eigenvectors of Â are better conditioned where the states' scales differ (positions
// against velocities, ω times larger). Returns the diagonal of D.
Eigen::VectorXd balance(Eigen::MatrixXd* A) {
  const Eigen::Index r = A->rows();
  Eigen::VectorXd d = Eigen::VectorXd::Ones(r);
  for (bool done = false; !done;) {
    done = true;
    for (Eigen::Index i = 0; i < r; ++i) {
      double c = A->col(i).cwiseAbs().sum() - std::abs((*A)(i, i));
      double row = A->row(i).cwiseAbs().sum() - std::abs((*A)(i, i));
      if (c == 0.0 || row == 0.0) continue;
      const double s = c + row;
      double f = 1.0;
      while (c < row / 2.0) f *= 2.0, c *= 4.0;
      while (c > row * 2.0) f /= 2.0, c /= 4.0;
      if ((c + row) / f < 0.95 * s) {
        done = false;
        d(i) *= f;
        A->row(i) /= f;
        A->col(i) *= f;
      }
    }
  }
  return d;
}

}  // namespace

std::unique_ptr<ModalRideMarch> ModalRideMarch::make(const RideStateSpace& model, const TrackUnderWheels& track,
                                                     const std::vector<OutputRow>& rows, double speed, double step,
                                                     double start) {
  // A = D Â D⁻¹ = (D V̂) Λ (D V̂)⁻¹: the test is on V̂, the basis the arithmetic uses.
  Eigen::MatrixXd balanced = model.A;
  const Eigen::VectorXd D = balance(&balanced);
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(balanced);
  if (eigen.info() != Eigen::Success) return nullptr;
  const Eigen::MatrixXcd& Vb = eigen.eigenvectors();  // unit columns
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXcd>(Vb).singularValues();
  const double condition = sigma(sigma.size() - 1) > 0.0 ? sigma(0) / sigma(sigma.size() - 1) : INFINITY;
  if (!(condition <= kModalConditionLimit)) return nullptr;
  const Eigen::MatrixXcd V = D.cast<Complex>().asDiagonal() * Vb;
  const Eigen::MatrixXcd W = Vb.partialPivLu().inverse() * D.cwiseInverse().cast<Complex>().asDiagonal();

  std::unique_ptr<ModalRideMarch> m(new ModalRideMarch());
  m->speed_ = speed;
  m->h_ = step;
  m->condition_ = condition;
  // One of each conjugate pair (Im λ > 0, counted twice in the real state) and every real mode
  // (EigenSolver gives those an exactly zero imaginary part and a real eigenvector).
  std::vector<int> marched;
  std::vector<double> weight;
  for (int k = 0; k < static_cast<int>(V.cols()); ++k) {
    const double im = eigen.eigenvalues()(k).imag();
    if (im < 0.0) continue;
    marched.push_back(k);
    weight.push_back(im > 0.0 ? 2.0 : 1.0);
  }
  m->modes_ = static_cast<int>(marched.size());
  for (int k : marched) {
    const Complex mu = std::exp(eigen.eigenvalues()(k) * step);
    m->lambda_.push_back(eigen.eigenvalues()(k));
    m->mu_re_.push_back(mu.real());
    m->mu_im_.push_back(mu.imag());
  }

  // Step k stands k/m samples on: m = Δx/(V h), whole (simulate_ride rounds h so); else the
  // dense march, which takes any step.
  m->step_ = track.step();
  m->periodic_ = track.periodic();
  m->per_sample_ = std::lround(m->step_ / (speed * step));
  if (m->per_sample_ < 1 ||
      std::abs(static_cast<double>(m->per_sample_) * speed * step - m->step_) > 1e-9 * m->step_)
    return nullptr;
  // The inputs at one track position (exactly the same lag) summed, per profile the track has.
  std::vector<double> lags;
  for (int i = 0; i < track.inputs(); ++i)
    if (std::find(lags.begin(), lags.end(), track.lag(i)) == lags.end()) lags.push_back(track.lag(i));
  m->outputs_ = static_cast<int>(rows.size());
  std::vector<double> lw, ld;
  for (double lag : lags) {
    // As RideMarch: a sample meets this position when start + V t − lag is a multiple of Δx.
    double delta = std::fmod((lag - start) / speed, step);
    if (delta < 0.0) delta += step;
    if (delta < 1e-9 * step || delta > (1.0 - 1e-9) * step) delta = 0.0;
    // Where it stands at step 0, in samples: a whole part and a fraction, within the same
    // 1e-9 of a sample as δ taken as on it.
    const double at = (start - lag) / m->step_;
    Eigen::Index base = static_cast<Eigen::Index>(std::floor(at));
    double phase = at - static_cast<double>(base);
    if (phase < 1e-9) phase = 0.0;
    if (phase > 1.0 - 1e-9) phase = 0.0, ++base;
    for (int p = 0; p < TrackUnderWheels::kProfiles; ++p) {
      const Eigen::VectorXd& profile = track.profile(p);
      if (profile.size() == 0) continue;
      Eigen::VectorXd load = Eigen::VectorXd::Zero(model.A.rows());
      Eigen::VectorXd lw_p = Eigen::VectorXd::Zero(m->outputs_), ld_p = Eigen::VectorXd::Zero(m->outputs_);
      for (int i = 0; i < track.inputs(); ++i) {
        if (track.lag(i) != lag) continue;
        const Eigen::Vector3d d = track.direction(i, p);
        load += model.B.middleCols(3 * i, 3) * d;
        for (int j = 0; j < m->outputs_; ++j) {
          lw_p(j) += rows[j].Lw.segment(3 * i, 3).dot(d);
          ld_p(j) += rows[j].Ld.segment(3 * i, 3).dot(d);
        }
      }
      Eigen::Index wrapped = base;
      if (m->periodic_) wrapped = (base % profile.size() + profile.size()) % profile.size();
      m->inputs_.push_back({&profile, wrapped, phase, delta, delta * speed / m->step_});
      for (int j = 0; j < m->outputs_; ++j) lw.push_back(lw_p(j)), ld.push_back(ld_p(j));
      // The march carries w = z − Q₂u(t) (Q₂ the end-of-step tap), so that a step reads the
      // inputs once: w(t + h) = μw(t) + (Q₀ + μQ₂)u(t) + Q₁u(t + δ), and z = w + Q₂u(t) goes
      // into the outputs' direct terms (below) and the conversions at the start and end.
      const Eigen::VectorXcd beta = W * load.cast<Complex>();
      std::vector<Complex> q0(m->modes_), q1(m->modes_);
      for (int k = 0; k < m->modes_; ++k) {
        Complex t[3];
        taps(m->lambda_[k], step, delta, t);
        const Complex mu(m->mu_re_[k], m->mu_im_[k]);
        q0[k] = (t[0] + mu * t[2]) * beta(marched[k]);
        q1[k] = t[1] * beta(marched[k]);
        const Complex q2 = t[2] * beta(marched[k]);
        m->end_re_.push_back(q2.real());
        m->end_im_.push_back(q2.imag());
      }
      const int input = static_cast<int>(m->inputs_.size()) - 1;
      for (int k = 0; k < m->modes_; ++k) m->q_re_.push_back(q0[k].real()), m->q_im_.push_back(q0[k].imag());
      m->tap_input_.push_back(input);
      m->tap_mid_.push_back(0);
      if (delta != 0.0) {  // no kink inside the step: no middle tap
        for (int k = 0; k < m->modes_; ++k) m->q_re_.push_back(q1[k].real()), m->q_im_.push_back(q1[k].imag());
        m->tap_input_.push_back(input);
        m->tap_mid_.push_back(1);
      }
    }
  }
  // lw_, ld_ stored output-major: lw_[j·inputs + i]
  const int n_in = static_cast<int>(m->inputs_.size());
  m->lw_.resize(lw.size());
  m->ld_.resize(ld.size());
  for (int i = 0; i < n_in; ++i)
    for (int j = 0; j < m->outputs_; ++j) {
      m->lw_[j * n_in + i] = lw[i * m->outputs_ + j];
      m->ld_[j * n_in + i] = ld[i * m->outputs_ + j];
    }
  m->slope_used_.assign(m->inputs_.size(), 0);
  for (int i = 0; i < n_in; ++i)
    for (int j = 0; j < m->outputs_; ++j) m->slope_used_[i] |= m->ld_[j * n_in + i] != 0.0;
  // Ls·s = Σ over marched modes of weight · Re((Ls·v_k) z_k)
  for (int j = 0; j < m->outputs_; ++j)
    for (int k = 0; k < m->modes_; ++k) {
      const Complex c = weight[k] * (rows[j].Ls.cast<Complex>() * V.col(marched[k])).value();
      m->c_re_.push_back(c.real());
      m->c_im_.push_back(c.imag());
    }
  // z = w + Q₂u: the Q₂u part of Ls·s is a direct term of each input, Σ_k Re(c_k Q₂_k)
  for (int j = 0; j < m->outputs_; ++j)
    for (int i = 0; i < n_in; ++i)
      for (int k = 0; k < m->modes_; ++k)
        m->lw_[j * n_in + i] += m->c_re_[j * m->modes_ + k] * m->end_re_[i * m->modes_ + k] -
                                m->c_im_[j * m->modes_ + k] * m->end_im_[i * m->modes_ + k];
  return m;
}

ModalRideMarch::State ModalRideMarch::rest() const {
  return {std::vector<double>(modes_, 0.0), std::vector<double>(modes_, 0.0)};
}

// One input's segment at the current step, counted in whole samples and steps (no position is
// ever formed as a double, so a wheel on a sample reads that sample exactly).
class ModalRideMarch::Cursor {
 public:
  Cursor(const ModalRideMarch& march, int input)
      : march_(march), in_(march.inputs_[input]), n_(in_.profile->size()), segment_(in_.base) {}
  void next() {
    if (++r_ < march_.per_sample_) {
      offset_ = static_cast<double>(r_) / static_cast<double>(march_.per_sample_);
      return;
    }
    r_ = 0;
    offset_ = 0.0;
    if (++segment_ == n_ && march_.periodic_) segment_ = 0;
  }
  // With one step a sample (m = 1) the input stands at the same fraction `phase` of each
  // segment, so the next steps read segments j, j + 1, … in a straight line: how many of the
  // next `limit` steps do so with a sample before and after each (no wrap, no record end),
  // and `skip` moves past them.
  long straight_run(long limit) const {
    if (march_.per_sample_ != 1 || segment_ < 1) return 0;
    return std::max<long>(0, std::min<long>(limit, n_ - 1 - segment_));
  }
  void skip(long steps) { segment_ += steps; }
  Eigen::Index segment() const { return segment_; }

  struct Place {
    Eigen::Index j, next;  // the segment [j, next] whose straight line is read (a record's end
                           // segments extended past its ends)
    double f;              // the fraction along it
    Eigen::Index at;       // the sample the input stands on (to 1e-9 of a sample), else −1
  };
  Place place() const {
    double f = in_.phase + offset_;
    Eigen::Index j = segment_;
    if (f >= 1.0) {
      f -= 1.0;
      if (++j == n_ && march_.periodic_) j = 0;
    }
    constexpr double kOnSample = 1e-9;  // as TrackUnderWheels::slope
    const Eigen::Index at = f < kOnSample ? j : f > 1.0 - kOnSample ? j + 1 : -1;
    if (!march_.periodic_ && j > n_ - 2) f += static_cast<double>(j - (n_ - 2)), j = n_ - 2;
    if (!march_.periodic_ && j < 0) f += static_cast<double>(j), j = 0;
    Eigen::Index next = j + 1;
    if (next == n_) next = 0;
    return {j, next, f, at};
  }

 private:
  const ModalRideMarch& march_;
  const Input& in_;
  Eigen::Index n_;
  Eigen::Index segment_;
  long r_ = 0;           // the step within the sample, 0 … m − 1
  double offset_ = 0.0;  // r/m
};

std::vector<ModalRideMarch::Cursor> ModalRideMarch::cursors() const {
  std::vector<Cursor> out;
  for (size_t i = 0; i < inputs_.size(); ++i) out.emplace_back(*this, static_cast<int>(i));
  return out;
}

// Blocks. The march goes over blocks of kSteps steps: every input of the block is read first
// (the reads do not depend on the state), then w is advanced step by step by a kernel whose
// state lives in registers (march_steps, the mode count a template argument), then the outputs
// of the block are summed step-wise across the block. Each step's arithmetic is the same
// operations in the same order as a step at a time, so the histories are the same bit for bit
// (ModalRideMarch.BlocksOfStepsChangeNoBit; the golden time-domain reports unchanged).
struct ModalRideMarch::Block {
  static constexpr long kSteps = 256;
  // input-major, [i · kSteps + b]: u(t), u(t + δ) (0 where δ = 0) and ∂u/∂ξ at step b
  std::vector<double> now, mid, slope;
  // mode-major, [m · kSteps + b]: w at step b, before that step's advance
  std::vector<double> w_re, w_im;
  Block(size_t inputs, int modes)
      : now(inputs * kSteps), mid(inputs * kSteps), slope(inputs * kSteps), w_re(modes * kSteps), w_im(modes * kSteps) {}
};

void ModalRideMarch::read_block(std::vector<Cursor>* cursors, long steps, Block* block, bool slopes) const {
  const long B = Block::kSteps;
  for (size_t i = 0; i < inputs_.size(); ++i) {
    const Input& in = inputs_[i];
    const Eigen::VectorXd& p = *in.profile;
    const Eigen::Index n = p.size();
    Cursor& cursor = (*cursors)[i];
    double* now = block->now.data() + i * B;
    double* mid = block->mid.data() + i * B;
    double* slope = block->slope.data() + i * B;
    const bool slopes_here = slopes && slope_used_[i];
    for (long b = 0; b < steps; ++b, cursor.next()) {
      if (const long run = cursor.straight_run(steps - b)) {
        // the same formulas as the step below, on a straight run (f = phase, on a sample iff 0)
        const double* q = p.data() + cursor.segment();
        const double f = in.phase, g = in.phase + in.reach;
        for (long t = 0; t < run; ++t) now[b + t] = q[t] + f * (q[t + 1] - q[t]);
        for (long t = 0; t < run; ++t) mid[b + t] = in.delta == 0.0 ? 0.0 : q[t] + g * (q[t + 1] - q[t]);
        if (slopes_here && f == 0.0)
          for (long t = 0; t < run; ++t) slope[b + t] = (q[t + 1] - q[t - 1]) / (2.0 * step_);
        else if (slopes_here)
          for (long t = 0; t < run; ++t) slope[b + t] = (q[t + 1] - q[t]) / step_;
        cursor.skip(run - 1);  // and the loop's next()
        b += run - 1;
        continue;
      }
      const Cursor::Place at = cursor.place();
      const double u0 = p(at.j), u1 = p(at.next);
      now[b] = u0 + at.f * (u1 - u0);
      mid[b] = in.delta == 0.0 ? 0.0 : u0 + (at.f + in.reach) * (u1 - u0);
      if (!slopes_here) continue;
      // as TrackUnderWheels::slope: on a sample the mean of its two segments; a record's first
      // and last samples take their one segment (the extended line beyond them)
      if (at.at < 0) {
        slope[b] = (u1 - u0) / step_;
        continue;
      }
      Eigen::Index before = at.at - 1, after = at.at + 1;
      if (periodic_) {
        if (before < 0) before += n;
        if (before >= n) before -= n;
        if (after >= n) after -= n;
        slope[b] = (p(after) - p(before)) / (2.0 * step_);
      } else if (before < 0) {
        slope[b] = (p(1) - p(0)) / step_;
      } else if (after > n - 1) {
        slope[b] = (p(n - 1) - p(n - 2)) / step_;
      } else {
        slope[b] = (p(after) - p(before)) / (2.0 * step_);
      }
    }
  }
}

namespace {

// One block of w ← μ∘w + Σ_taps q·v, `steps` steps; w before each step kept in kept_re/kept_im
// (mode-major, `stride` apart) when they are given. kModes > 0: the mode count fixed, so that
// w is a local array the compiler keeps in registers; 0: any count, w in memory.
template <int kModes>
void march_steps(int modes, const double* mu_re, const double* mu_im, const double* q_re, const double* q_im,
                 const std::vector<const double*>& taps, long steps, double* state_re, double* state_im,
                 double* kept_re, double* kept_im, long stride) {
  constexpr bool fixed = kModes > 0;
  const int M = fixed ? kModes : modes;
  double local_re[fixed ? kModes : 1], local_im[fixed ? kModes : 1];
  double* wr = fixed ? local_re : state_re;
  double* wi = fixed ? local_im : state_im;
  if (fixed)
    for (int m = 0; m < M; ++m) wr[m] = state_re[m], wi[m] = state_im[m];
  const size_t count = taps.size();
  for (long b = 0; b < steps; ++b) {
    if (kept_re)
      for (int m = 0; m < M; ++m) kept_re[m * stride + b] = wr[m], kept_im[m * stride + b] = wi[m];
    for (int m = 0; m < M; ++m) {
      const double r = mu_re[m] * wr[m] - mu_im[m] * wi[m];
      wi[m] = mu_re[m] * wi[m] + mu_im[m] * wr[m];
      wr[m] = r;
    }
    for (size_t t = 0; t < count; ++t) {
      const double v = taps[t][b];
      const double* qr = q_re + t * M;
      const double* qi = q_im + t * M;
      for (int m = 0; m < M; ++m) {
        wr[m] += qr[m] * v;
        wi[m] += qi[m] * v;
      }
    }
  }
  if (fixed)
    for (int m = 0; m < M; ++m) state_re[m] = wr[m], state_im[m] = wi[m];
}

using MarchKernel = void (*)(int, const double*, const double*, const double*, const double*,
                             const std::vector<const double*>&, long, double*, double*, double*, double*, long);
// march_steps<0> (any count), then march_steps<1> … march_steps<16>: up to 16 marched modes
// (a 16-DOF vehicle's conjugate pairs) the state stays in registers.
template <int... M>
constexpr std::array<MarchKernel, sizeof...(M) + 1> march_kernels(std::integer_sequence<int, M...>) {
  return {&march_steps<0>, &march_steps<M + 1>...};
}
constexpr auto kMarchKernels = march_kernels(std::make_integer_sequence<int, 16>{});

}  // namespace

void ModalRideMarch::advance_block(Block* block, long steps, State* w, bool keep) const {
  std::vector<const double*> taps(tap_input_.size());
  for (size_t t = 0; t < taps.size(); ++t)
    taps[t] = (tap_mid_[t] ? block->mid.data() : block->now.data()) + tap_input_[t] * Block::kSteps;
  const MarchKernel kernel = modes_ < static_cast<int>(kMarchKernels.size()) ? kMarchKernels[modes_] : kMarchKernels[0];
  kernel(modes_, mu_re_.data(), mu_im_.data(), q_re_.data(), q_im_.data(), taps, steps, w->re.data(), w->im.data(),
         keep ? block->w_re.data() : nullptr, keep ? block->w_im.data() : nullptr, Block::kSteps);
}

void ModalRideMarch::shift(State* s, const std::vector<double>& now, double sign) const {
  for (size_t i = 0; i < inputs_.size(); ++i)
    for (int m = 0; m < modes_; ++m) {
      s->re[m] += sign * end_re_[i * modes_ + m] * now[i];
      s->im[m] += sign * end_im_[i * modes_ + m] * now[i];
    }
}

bool ModalRideMarch::periodic_start(long period, State* start) {
  const size_t n_in = inputs_.size();
  Block block(n_in, modes_);
  std::vector<double> first(n_in);
  std::vector<Cursor> cursor = cursors();
  // w from rest over one period: its orbit's start is w_P / (1 − μ^period) as z's (the same
  // recurrence, the same periodic inputs), and z* = w* + Q₂u(0).
  State z = rest();
  for (long k = 0; k < period; k += Block::kSteps) {
    const long steps = std::min(Block::kSteps, period - k);
    read_block(&cursor, steps, &block, false);
    if (k == 0)
      for (size_t i = 0; i < n_in; ++i) first[i] = block.now[i * Block::kSteps];
    advance_block(&block, steps, &z, false);
  }
  if (period <= 0) {
    read_block(&cursor, 1, &block, false);
    for (size_t i = 0; i < n_in; ++i) first[i] = block.now[i * Block::kSteps];
  }
  std::vector<Complex> gain(modes_);
  double least = INFINITY, most = 0.0;
  for (int m = 0; m < modes_; ++m) {
    gain[m] = 1.0 - std::exp(lambda_[m] * (h_ * static_cast<double>(period)));
    least = std::min(least, std::abs(gain[m]));
    most = std::max(most, std::abs(gain[m]));
  }
  constexpr double kSingular = 1e-10;  // as the dense path's reciprocal condition of I − Φ^period
  if (!(least >= kSingular * most)) {
    *start = rest();
    return false;
  }
  for (int m = 0; m < modes_; ++m) {
    const Complex s = Complex(z.re[m], z.im[m]) / gain[m];
    z.re[m] = s.real();
    z.im[m] = s.imag();
  }
  shift(&z, first, 1.0);
  *start = std::move(z);
  return true;
}

std::vector<Eigen::VectorXd> ModalRideMarch::outputs(State z, long count) {
  const size_t n_in = inputs_.size();
  const long B = Block::kSteps;
  std::vector<Eigen::VectorXd> y(outputs_);
  for (Eigen::VectorXd& column : y) column.resize(count);
  Block block(n_in, modes_);
  std::vector<Cursor> cursor = cursors();
  for (long k0 = 0; k0 < count; k0 += B) {
    const long steps = std::min(B, count - k0);
    read_block(&cursor, steps, &block, true);
    if (k0 == 0) {  // w = z − Q₂u(0)
      std::vector<double> first(n_in);
      for (size_t i = 0; i < n_in; ++i) first[i] = block.now[i * B];
      shift(&z, first, -1.0);
    }
    // (the advance after the last step is not used)
    advance_block(&block, steps, &z, true);
    for (int j = 0; j < outputs_; ++j) {  // summed in place in the output's history
      double* sum = y[j].data() + k0;
      std::fill(sum, sum + steps, 0.0);
      for (int m = 0; m < modes_; ++m) {
        const double cr = c_re_[j * modes_ + m], ci = c_im_[j * modes_ + m];
        const double* wr = block.w_re.data() + m * B;
        const double* wi = block.w_im.data() + m * B;
        for (long b = 0; b < steps; ++b) sum[b] += cr * wr[b] - ci * wi[b];
      }
      for (size_t i = 0; i < n_in; ++i) {
        const double lw = lw_[j * n_in + i], vld = speed_ * ld_[j * n_in + i];
        const double* now = block.now.data() + i * B;
        const double* slope = block.slope.data() + i * B;
        if (slope_used_[i]) {
          for (long b = 0; b < steps; ++b) sum[b] += lw * now[b] + vld * slope[b];
        } else {  // vld = 0: the term is a zero, which changes lw·u only in an exact zero's sign
          for (long b = 0; b < steps; ++b) sum[b] += lw * now[b];
        }
      }
    }
  }
  return y;
}

}  // namespace railmodal::ride
