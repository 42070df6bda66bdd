// Exact state-transition integration of a linear scene (first-order hold on the load).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

#include "railmodal/errors.hpp"
#include "railmodal/simulation.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

Eigen::MatrixXd take(const Eigen::MatrixXd& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) out(i, j) = A(rows[i], cols[j]);
  return out;
}

// One harmonic of the load, F(t) = Re(Q e^{iωt}); its phase e^{iωt} advances by rotation.
struct Harmonic {
  Eigen::VectorXcd retained;  // Q on the retained DOFs after condensation
  Eigen::VectorXcd massless;  // Q on the massless DOFs (for their static recovery)
  double omega = 0.0;
  std::complex<double> turn;  // e^{iωΔt}
  std::complex<double> phase{1.0, 0.0};
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

}  // namespace

TimeHistory simulate_linear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                            const SimulationOptions& options) {
  const int n = system.size();
  if (n == 0) throw std::invalid_argument("simulation: the system has no degrees of freedom");
  if (!(options.duration > 0.0) || !(options.time_step > 0.0) || !std::isfinite(options.duration))
    throw std::invalid_argument("simulation: duration and time step must be positive");
  if (options.duration / options.time_step > 1e8)
    throw std::invalid_argument("simulation: more than 1e8 steps; take a longer time step");
  if (!sources.empty() && !(options.speed > 0.0)) throw std::invalid_argument("simulation: the speed must be positive");
  const int steps = static_cast<int>(std::llround(options.duration / options.time_step));
  const double h = options.time_step;

  const Partition p = partition(system);
  const int r = static_cast<int>(p.kept.size());
  const Transition T = transition(p, h);

  // The sources as harmonics of the load, condensed onto the kept DOFs: F_r + Sᵀ F_m.
  std::vector<Harmonic> harmonics;
  for (const ExcitationSource* source : sources)
    for (int k = 1; k <= source->harmonic_count(); ++k) {
      const HarmonicLoad load = source->load(system, options.speed, k);
      const Eigen::VectorXcd Q = generalized_load(system, load);
      if (Q.norm() == 0.0) continue;
      Harmonic hk;
      hk.retained.resize(r);
      for (int i = 0; i < r; ++i) hk.retained(i) = Q(p.kept[i]);
      hk.massless.resize(p.massless.size());
      for (size_t m = 0; m < p.massless.size(); ++m) hk.massless(m) = Q(p.massless[m]);
      if (!p.massless.empty()) hk.retained += p.S.transpose().cast<std::complex<double>>() * hk.massless;
      hk.omega = kTwoPi * load.frequency_hz;
      hk.turn = std::exp(std::complex<double>(0.0, hk.omega * h));
      harmonics.push_back(hk);
    }
  auto load_now = [&](Eigen::VectorXd* F) {
    F->setZero();
    for (const auto& hk : harmonics) *F += (hk.retained * hk.phase).real();
  };

  Eigen::VectorXd s = Eigen::VectorXd::Zero(2 * r);
  for (const auto& ic : options.initial) {
    const int d = system.index_of(ic.dof);
    if (d < 0) throw std::invalid_argument("simulation: initial condition on unknown DOF '" + ic.dof + "'");
    const auto at = std::find(p.kept.begin(), p.kept.end(), d);
    if (at == p.kept.end())
      throw std::invalid_argument("simulation: '" + ic.dof + "' is massless; it follows the others statically");
    s(at - p.kept.begin()) = ic.displacement;
    s(r + (at - p.kept.begin())) = ic.velocity;
  }

  TimeHistory out;
  for (const auto& d : system.dofs) out.labels.push_back(d.label);
  out.time.resize(steps + 1);
  out.displacement.resize(steps + 1, n);
  out.velocity.resize(steps + 1, n);
  auto record = [&](int i) {
    out.time(i) = i * h;
    for (int j = 0; j < r; ++j) {
      out.displacement(i, p.kept[j]) = s(j);
      out.velocity(i, p.kept[j]) = s(r + j);
    }
    if (p.massless.empty()) return;
    // Static recovery x_m = S x_r + P F_m, v_m = S v_r + P Ḟ_m.
    Eigen::VectorXd Fm = Eigen::VectorXd::Zero(p.massless.size()), dFm = Fm;
    for (const auto& hk : harmonics) {
      Fm += (hk.massless * hk.phase).real();
      dFm += (hk.massless * (std::complex<double>(0.0, hk.omega) * hk.phase)).real();
    }
    const Eigen::VectorXd xm = p.S * s.head(r) + p.P * Fm;
    const Eigen::VectorXd vm = p.S * s.tail(r) + p.P * dFm;
    for (size_t m = 0; m < p.massless.size(); ++m) {
      out.displacement(i, p.massless[m]) = xm(m);
      out.velocity(i, p.massless[m]) = vm(m);
    }
  };

  Eigen::VectorXd F(r), F_next(r);
  load_now(&F);
  record(0);
  for (int i = 1; i <= steps; ++i) {
    for (auto& hk : harmonics) hk.phase *= hk.turn;
    load_now(&F_next);
    s = T.Phi * s + T.Gamma0 * F + T.Gamma1 * (F_next - F);
    F.swap(F_next);
    record(i);
  }
  return out;
}

}  // namespace railmodal
