// Exact state-transition integration of a linear scene (first-order hold on the load).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

#include "model/analysis_limits.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/simulation.hpp"
#include "require_valid.hpp"
#include "simulate/history_summary.hpp"
#include "simulate/sample_count.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

Eigen::MatrixXd take(const Eigen::MatrixXd& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) out(i, j) = A(rows[i], cols[j]);
  return out;
}

// One harmonic of the load, F(t) = Re(Q e^{iωt}).
struct Harmonic {
  Eigen::VectorXcd retained;  // Q on the retained DOFs after condensation
  Eigen::VectorXcd massless;  // Q on the massless DOFs (for their static recovery)
  double omega = 0.0;
  std::complex<double> turn;  // e^{iωΔt}
};

// The model split into DOFs with mass (integrated) and massless DOFs (recovered statically).
struct Partition {
  std::vector<int> kept, massless;
  Eigen::MatrixXd M, C, K;  // on kept, K condensed
  Eigen::MatrixXd S, P;     // x_m = S x_r + P F_m
};

Partition partition(const LinearSystem& system) {
  Partition p;
  const int n = system.size();
  for (int i = 0; i < n; ++i) (system.mass.row(i).cwiseAbs().maxCoeff() == 0.0 ? p.massless : p.kept).push_back(i);
  if (p.kept.empty()) throw NumericalError("every degree of freedom is massless");
  p.M = take(system.mass, p.kept, p.kept);
  p.C = take(system.damping, p.kept, p.kept);
  p.K = take(system.stiffness, p.kept, p.kept);
  if (p.massless.empty()) return p;
  if (take(system.damping, p.massless, p.massless).cwiseAbs().maxCoeff() > 0.0 ||
      take(system.damping, p.massless, p.kept).cwiseAbs().maxCoeff() > 0.0)
    throw std::invalid_argument("simulation: a massless degree of freedom carries a damper (first-order "
                                "dynamics are not supported); give it inertia");
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(take(system.stiffness, p.massless, p.massless));
  if (!lu.isInvertible()) throw NumericalError("a massless degree of freedom has no restraint");
  p.P = lu.inverse();
  p.S = -p.P * take(system.stiffness, p.massless, p.kept);
  p.K += take(system.stiffness, p.kept, p.massless) * p.S;
  return p;
}

// Φ = e^{Ah}, Γ0 = ∫₀ʰ e^{As} ds B and Γ1 = (1/h)∫₀ʰ e^{A(h−s)} s ds B from one exponential
// (Van Loan): exp([[A, B, 0], [0, 0, I/h], [0, 0, 0]]·h). Then, for a load linear over the
// step, s⁺ = Φ s + Γ0 F + Γ1 (F⁺ − F) exactly.
struct Transition {
  Eigen::MatrixXd Phi, Gamma0, Gamma1;
};

Transition transition(const Partition& p, double h) {
  const int r = static_cast<int>(p.kept.size());
  const Eigen::LLT<Eigen::MatrixXd> llt(p.M);
  if (llt.info() != Eigen::Success) throw NumericalError("the mass matrix is not positive definite");
  const Eigen::MatrixXd Minv = llt.solve(Eigen::MatrixXd::Identity(r, r));
  const int N = 4 * r;
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(N, N);
  E.block(0, r, r, r) = Eigen::MatrixXd::Identity(r, r) * h;  // ẋ = v
  E.block(r, 0, r, r) = -Minv * p.K * h;                      // v̇ = −M⁻¹K x − M⁻¹C v + M⁻¹F
  E.block(r, r, r, r) = -Minv * p.C * h;
  E.block(r, 2 * r, r, r) = Minv * h;                         // B·h, B = [0; M⁻¹]
  E.block(2 * r, 3 * r, r, r).setIdentity();                  // (I/h)·h
  const Eigen::MatrixXd X = E.exp();
  Transition t{X.topLeftCorner(2 * r, 2 * r), X.block(0, 2 * r, 2 * r, r), X.block(0, 3 * r, 2 * r, r)};
  if (!t.Phi.allFinite() || !t.Gamma0.allFinite() || !t.Gamma1.allFinite())
    throw NumericalError("simulation: the state transition overflowed (an unstable vehicle over this step?)");
  return t;
}

// y = G z for G column-major R × cols, R a multiple of kRows (8): a block of K rows at a time,
// their sums held in registers (fixed-size Eigen vectors, so SIMD packets) over all the
// columns. Each y(i) adds its terms in column order whatever K and the packet width, so every
// build gives the same bits. Blocks of 16 rows keep enough independent sums in flight to hide
// the latency of the additions; about 1.25× faster than Eigen's general matrix-vector product
// at these sizes (32 × 44 for a 15-DOF vehicle), which loads and stores y for every column.
constexpr int kRows = 8;
template <int K>
void rows_times(const double* G, int R, int cols, const double* z, double* y) {
  using Block = Eigen::Matrix<double, K, 1>;
  Block sum = Block::Zero();
  for (int j = 0; j < cols; ++j, G += R) sum += Eigen::Map<const Block>(G) * z[j];
  Eigen::Map<Block> out(y);
  out = sum;
}
void next_state(const double* G, int R, int cols, const double* z, double* y) {
  int i0 = 0;
  for (; i0 + 2 * kRows <= R; i0 += 2 * kRows) rows_times<2 * kRows>(G + i0, R, cols, z, y + i0);
  if (i0 < R) rows_times<kRows>(G + i0, R, cols, z, y + i0);
}

// The sources as harmonics of the load, condensed onto the kept DOFs: F_r + Sᵀ F_m.
std::vector<Harmonic> condensed_harmonics(const LinearSystem& system,
                                          const std::vector<const ExcitationSource*>& sources, double speed,
                                          const Partition& p, double h) {
  const int r = static_cast<int>(p.kept.size()), m = static_cast<int>(p.massless.size());
  std::vector<Harmonic> harmonics;
  for (const ExcitationSource* source : sources)
    for (int k = 1; k <= source->harmonic_count(); ++k) {
      const HarmonicLoad load = source->load(system, speed, k);
      const Eigen::VectorXcd Q = generalized_load(system, load);
      if (Q.norm() == 0.0) continue;
      Harmonic hk;
      hk.retained.resize(r);
      for (int i = 0; i < r; ++i) hk.retained(i) = Q(p.kept[i]);
      hk.massless.resize(m);
      for (int j = 0; j < m; ++j) hk.massless(j) = Q(p.massless[j]);
      if (m > 0) hk.retained += p.S.transpose().cast<std::complex<double>>() * hk.massless;
      hk.omega = kTwoPi * load.frequency_hz;
      hk.turn = std::exp(std::complex<double>(0.0, hk.omega * h));
      harmonics.push_back(hk);
    }
  return harmonics;
}

// The vector z = [s; 0…; Re p_1, Im p_1, …] that a step multiplies: the state s = (x_r, v_r)
// padded with zeros to R rows, a multiple of kRows (see next_state), then the phase
// p_k = e^{iω_k t} of each harmonic.
struct StepVector {
  int r = 0;  // retained DOFs
  int R = 0;  // rows of the padded state
  int H = 0;  // harmonics
  int size() const { return R + 2 * H; }
  int phase(int k) const { return R + 2 * k; }  // Re p_k, followed by Im p_k
};

// The whole step as one product. With p_k = e^{iω_k t} at the start of a step the load is
// F = Σ Re(Q_k p_k) and at its end F⁺ = Σ Re(Q_k p_k e^{iω_k Δt}), so
//   s⁺ = Φ s + (Γ0 − Γ1) F + Γ1 F⁺ = Φ s + Σ Re(W_k p_k),  W_k = (Γ0 − Γ1 + Γ1 e^{iω_k Δt}) Q_k,
// and with z as above, s⁺ = G z, G = [Φ | Re W_1, −Im W_1 | …]: one product per step instead
// of the loads and three products, the input folded into the transition once.
Eigen::MatrixXd step_matrix(const Transition& T, const std::vector<Harmonic>& harmonics, const StepVector& z) {
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(z.R, z.size());
  G.topLeftCorner(2 * z.r, 2 * z.r) = T.Phi;
  for (int k = 0; k < z.H; ++k) {
    const auto& hk = harmonics[k];
    const Eigen::VectorXcd W = (T.Gamma0 - T.Gamma1).cast<std::complex<double>>() * hk.retained +
                               T.Gamma1.cast<std::complex<double>>() * (hk.retained * hk.turn);
    G.col(z.phase(k)).head(2 * z.r) = W.real();
    G.col(z.phase(k) + 1).head(2 * z.r) = -W.imag();
  }
  return G;
}

Eigen::VectorXd initial_z(const LinearSystem& system, const SimulationOptions& options, const Partition& p,
                          const StepVector& z) {
  Eigen::VectorXd z0 = Eigen::VectorXd::Zero(z.size());
  for (const auto& ic : options.initial) {
    const int d = system.index_of(ic.dof);
    if (d < 0) throw std::invalid_argument("simulation: initial condition on unknown DOF '" + ic.dof + "'");
    const auto at = std::find(p.kept.begin(), p.kept.end(), d);
    if (at == p.kept.end())
      throw std::invalid_argument("simulation: '" + ic.dof + "' is massless; it follows the others statically");
    z0(at - p.kept.begin()) = ic.displacement;
    z0(z.r + (at - p.kept.begin())) = ic.velocity;
  }
  for (int k = 0; k < z.H; ++k) z0(z.phase(k)) = 1.0;  // p_k = 1 at t = 0
  return z0;
}

// Static recovery of the massless DOFs, x_m = S x_r + P F_m and v_m = S v_r + P Ḟ_m, as
// products on z too: F_m = Σ Re(Q_mk p_k), Ḟ_m = Σ Re(iω_k Q_mk p_k).
struct MasslessRecovery {
  Eigen::MatrixXd Rx, Rv;
};

MasslessRecovery massless_recovery(const Partition& p, const std::vector<Harmonic>& harmonics, const StepVector& z) {
  const int m = static_cast<int>(p.massless.size());
  MasslessRecovery rec{Eigen::MatrixXd::Zero(m, z.size()), Eigen::MatrixXd::Zero(m, z.size())};
  if (m == 0) return rec;
  rec.Rx.leftCols(z.r) = p.S;
  rec.Rv.middleCols(z.r, z.r) = p.S;
  for (int k = 0; k < z.H; ++k) {
    const auto& hk = harmonics[k];
    const Eigen::VectorXcd PQ = p.P.cast<std::complex<double>>() * hk.massless;
    const Eigen::VectorXcd PdQ = PQ * std::complex<double>(0.0, hk.omega);
    rec.Rx.col(z.phase(k)) = PQ.real();
    rec.Rx.col(z.phase(k) + 1) = -PQ.imag();
    rec.Rv.col(z.phase(k)) = PdQ.real();
    rec.Rv.col(z.phase(k) + 1) = -PdQ.imag();
  }
  return rec;
}

// The phases advance by rotation, p ← p e^{iωΔt}; they are reset to e^{iωt} from t every
// kResync steps so that the rounding of the rotations does not build up over long records.
constexpr int kResync = 1024;

void advance_phases(const std::vector<Harmonic>& harmonics, const StepVector& z, int i, double h, const double* prev,
                    double* next) {
  if (i % kResync == 0) {
    for (int k = 0; k < z.H; ++k) {
      const std::complex<double> pk = std::polar(1.0, harmonics[k].omega * (i * h));
      next[z.phase(k)] = pk.real();
      next[z.phase(k) + 1] = pk.imag();
    }
  } else {
    for (int k = 0; k < z.H; ++k) {
      const std::complex<double> pk =
          std::complex<double>(prev[z.phase(k)], prev[z.phase(k) + 1]) * harmonics[k].turn;
      next[z.phase(k)] = pk.real();
      next[z.phase(k) + 1] = pk.imag();
    }
  }
}

// March in blocks of kBlock steps through a small buffer of z (one column per step, in
// cache), then hand each block to the sink as rows of samples (the transposition is done a
// cache-sized block at a time, and the loop itself allocates nothing). Returns whether every
// sample was finite.
bool march(const Eigen::MatrixXd& G, const MasslessRecovery& rec, const std::vector<Harmonic>& harmonics,
           const Partition& p, const StepVector& z, const Eigen::VectorXd& z0, double h, int steps, HistorySink& sink) {
  constexpr int kBlock = 128;
  const int r = z.r, m = static_cast<int>(p.massless.size());
  const int n = r + m;
  Eigen::MatrixXd buffer(z.size(), kBlock);
  Eigen::MatrixXd xm(m, kBlock), vm(m, kBlock);
  Eigen::MatrixXd x(kBlock, n), v(kBlock, n);
  Eigen::VectorXd time(kBlock);
  bool finite = true;
  buffer.col(0) = z0;
  for (int first = 0; first <= steps; first += kBlock) {
    const int count = std::min(kBlock, steps + 1 - first);
    for (int c = (first == 0 ? 1 : 0); c < count; ++c) {
      const auto prev = buffer.col(c == 0 ? kBlock - 1 : c - 1);
      auto next = buffer.col(c);
      next_state(G.data(), z.R, z.size(), prev.data(), next.data());
      advance_phases(harmonics, z, first + c, h, prev.data(), next.data());
    }
    for (int c = 0; c < count; ++c) time(c) = (first + c) * h;
    const auto block = buffer.leftCols(count);
    for (int j = 0; j < r; ++j) {
      x.col(p.kept[j]).head(count) = block.row(j).transpose();
      v.col(p.kept[j]).head(count) = block.row(r + j).transpose();
    }
    if (m > 0) {
      xm.leftCols(count).noalias() = rec.Rx * block;
      vm.leftCols(count).noalias() = rec.Rv * block;
      for (int j = 0; j < m; ++j) {
        x.col(p.massless[j]).head(count) = xm.row(j).head(count).transpose();
        v.col(p.massless[j]).head(count) = vm.row(j).head(count).transpose();
      }
    }
    finite = finite && x.topRows(count).allFinite() && v.topRows(count).allFinite();
    sink.write(time.head(count), x.topRows(count), v.topRows(count));
  }
  return finite;
}

}  // namespace

TimeHistory simulate_linear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                            const SimulationOptions& options) {
  return simulate::recorded([&](HistorySink& sink) { return simulate_linear(system, sources, options, sink); });
}

TimeHistory simulate_linear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                            const SimulationOptions& options, HistorySink& sink) {
  const int n = system.size();
  model::refuse_series_dampers(system, "simulation");
  if (n == 0) throw std::invalid_argument("simulation: the system has no degrees of freedom");
  require_valid(options, "simulation: ");
  if (options.duration / options.time_step > 1e8)
    throw std::invalid_argument("simulation: more than 1e8 steps; take a longer time step");
  if (!sources.empty() && !(options.speed > 0.0)) throw std::invalid_argument("simulation: the speed must be positive");
  if (options.final_speed > 0.0)
    throw std::invalid_argument("simulation: a speed ramp changes the load's frequency; the state transition holds it "
                                "fixed (simulate_nonlinear takes ramps, with or without nonlinear effects)");
  const int steps = static_cast<int>(simulate::sample_count(options.duration, options.time_step) - 1);
  const double h = options.time_step;
  AnalysisSummary summary;
  StageClock clock(&summary);

  const Partition p = partition(system);
  const Transition T = transition(p, h);
  const std::vector<Harmonic> harmonics = condensed_harmonics(system, sources, options.speed, p, h);
  StepVector z;
  z.r = static_cast<int>(p.kept.size());
  z.R = (2 * z.r + kRows - 1) / kRows * kRows;
  z.H = static_cast<int>(harmonics.size());
  const Eigen::MatrixXd G = step_matrix(T, harmonics, z);
  const Eigen::VectorXd z0 = initial_z(system, options, p, z);
  const MasslessRecovery recovery = massless_recovery(p, harmonics, z);
  clock.lap("state transition");

  TimeHistory out;
  for (const auto& d : system.dofs) out.labels.push_back(d.label);
  sink.begin(out.labels, steps + 1);
  const bool finite = march(G, recovery, harmonics, p, z, z0, h, steps, sink);
  clock.lap("march");
  simulate::summarise_history(&out, steps + 1, finite, std::move(summary), "time history, linear",
                              "exact state transition e^{AΔt} with first-order-hold load (Van Loan)");
  return out;
}

}  // namespace railmodal
