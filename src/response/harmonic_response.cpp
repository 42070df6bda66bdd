// Steady harmonic response: direct solve and modal superposition.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/analysis_limits.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/response.hpp"
#include "response/modal_checks.hpp"
#include "shortest_text.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
// ω² within this fraction of λ counts as exactly at the natural frequency: critical speeds
// are computed as V = Λf/k, which returns ω² to within a few ulps.
constexpr double kAtResonance = 1e-9;

double modal_damping(const LinearSystem& system, const Mode& mode) {
  return mode.shape.dot(system.damping * mode.shape);
}

// Undamped modes at ω. With C positive semi-definite, φᵀCφ = 0 means Cφ = 0, so each is a
// null vector of the dynamic stiffness D = K − ω²M + iωC.
void undamped_modes_at(const LinearSystem& system, const ModalResult& modes, double omega,
                       std::vector<const Mode*>* at) {
  at->clear();
  for (const Mode& m : modes.modes)
    if (m.kind == ModeKind::oscillatory && std::abs(m.eigenvalue - omega * omega) <= kAtResonance * m.eigenvalue &&
        response::undamped(system, m))
      at->push_back(&m);
}

// A load drives a mode unless its modal force is round-off of ‖φ‖ times the source's total
// load (response::kLoadRoundOff): a symmetry zero, or a harmonic that is itself round-off.
bool drives(const Mode& mode, const Eigen::VectorXcd& load, double source_load) {
  return response::modal_force(mode, load, source_load) != 0.0;
}

void check_sizes(const LinearSystem& system, const ModalResult& modes, const Eigen::VectorXcd& load,
                 double frequency_hz) {
  if (load.size() != system.size() || static_cast<int>(modes.dofs.size()) != system.size())
    throw std::invalid_argument("harmonic response: load, modes and system sizes differ");
  if (!(frequency_hz >= 0.0) || !std::isfinite(frequency_hz))
    throw std::invalid_argument("harmonic response: frequency must be finite and non-negative");
}

}  // namespace

const char* to_string(ResponseQuantity quantity) {
  switch (quantity) {
    case ResponseQuantity::displacement: return "displacement";
    case ResponseQuantity::velocity: return "velocity";
    case ResponseQuantity::acceleration: return "acceleration";
  }
  return "?";
}

std::optional<ResponseQuantity> response_quantity_from_string(const std::string& word) {
  for (ResponseQuantity q : {ResponseQuantity::displacement, ResponseQuantity::velocity, ResponseQuantity::acceleration})
    if (word == to_string(q)) return q;
  return std::nullopt;
}

double response_amplitude(const HarmonicResponse& response, int dof, ResponseQuantity quantity) {
  const double omega = kTwoPi * response.frequency_hz;
  const double x = std::abs(response.displacement(dof));
  switch (quantity) {
    case ResponseQuantity::displacement: return x;
    case ResponseQuantity::velocity: return omega * x;
    case ResponseQuantity::acceleration: return omega * omega * x;
  }
  return x;
}

bool unbounded_at(const HarmonicResponse& response, const ModalResult& modes, int dof) {
  for (int index : response.resonant_modes) {
    const Eigen::VectorXd& shape = modes.modes[index - 1].shape;
    if (std::abs(shape(dof)) > 1e-9 * shape.cwiseAbs().maxCoeff()) return true;
  }
  return false;
}

HarmonicResponse harmonic_response(const LinearSystem& system, const ModalResult& modes, const Eigen::VectorXcd& load,
                                   double frequency_hz, double source_load_norm) {
  model::refuse_series_dampers(system, "harmonic response");
  check_sizes(system, modes, load, frequency_hz);
  const double source_load = std::max(source_load_norm, load.norm());
  HarmonicResponse out;
  out.frequency_hz = frequency_hz;
  const int n = system.size();
  const double omega = kTwoPi * frequency_hz;
  const std::complex<double> i(0.0, 1.0);
  // The matrix, its LU, the vectors and the list of undamped modes are this thread's, kept
  // between calls: a study solves one such system per resonance of every variant, all of one
  // size, and each call made them anew. The same operations on the same values: the same bits.
  thread_local std::vector<const Mode*> at;
  undamped_modes_at(system, modes, omega, &at);
  const int r = static_cast<int>(at.size());
  // D bordered by Mφ of the undamped modes at ω: the rest x ⟂_M φ solves
  // D x = Q − Σ Mφ (φᵀQ); without such modes it is plain D x = Q.
  // Every block but the border's corner is written below: only that corner is zeroed.
  thread_local Eigen::MatrixXcd A;
  thread_local Eigen::VectorXcd rhs, x, residual_vector, b;
  thread_local Eigen::VectorXd mass_shape;  // Mφ, the product (system.mass * φ) evaluated as before
  thread_local Eigen::PartialPivLU<Eigen::MatrixXcd> lu;
  A.resize(n + r, n + r);
  A.bottomRightCorner(r, r).setZero();
  A.topLeftCorner(n, n) = (system.stiffness - omega * omega * system.mass).cast<std::complex<double>>() +
                          i * omega * system.damping.cast<std::complex<double>>();
  rhs.setZero(n + r);
  rhs.head(n) = load;
  for (int k = 0; k < r; ++k) {
    mass_shape.noalias() = system.mass * at[k]->shape;
    b = mass_shape.cast<std::complex<double>>();
    A.block(0, n + k, n, 1) = b;
    A.block(n + k, 0, 1, n) = b.transpose();
    rhs.head(n) -= b * at[k]->shape.cast<std::complex<double>>().dot(load);
    if (drives(*at[k], load, source_load)) out.resonant_modes.push_back(at[k]->index);
  }
  lu.compute(A);
  x = lu.solve(rhs);
  residual_vector.noalias() = A * x;
  residual_vector -= rhs;
  const double residual = residual_vector.norm();
  // A load on a direction nothing restrains (a rigid-body mode at ω = 0) has no steady state.
  if (!x.allFinite() || !(residual <= 1e-8 * (rhs.norm() + A.norm() * x.norm())))
    throw NumericalError("harmonic response at " + shortest_text(frequency_hz, 6) +
                         " Hz: the dynamic stiffness is singular for this load (an unrestrained direction?)");
  out.displacement = x.head(n);
  out.unbounded = !out.resonant_modes.empty();
  out.resonant_mode = out.unbounded ? out.resonant_modes.front() : 0;
  return out;
}

HarmonicResponse modal_harmonic_response(const LinearSystem& system, const ModalResult& modes,
                                         const Eigen::VectorXcd& load, double frequency_hz, int mode_count,
                                         double source_load_norm) {
  model::refuse_series_dampers(system, "harmonic response");
  check_sizes(system, modes, load, frequency_hz);
  const double source_load = std::max(source_load_norm, load.norm());  // as harmonic_response
  HarmonicResponse out;
  out.frequency_hz = frequency_hz;
  const double omega = kTwoPi * frequency_hz;
  out.displacement = Eigen::VectorXcd::Zero(system.size());
  const int count = mode_count > 0 ? std::min<int>(mode_count, static_cast<int>(modes.modes.size()))
                                   : static_cast<int>(modes.modes.size());
  const std::complex<double> i(0.0, 1.0);
  for (int j = 0; j < count; ++j) {
    const Mode& mode = modes.modes[j];
    const Eigen::VectorXcd phi = mode.shape.cast<std::complex<double>>();
    const double c = modal_damping(system, mode);
    if (mode.kind == ModeKind::oscillatory && response::undamped(system, mode) &&
        std::abs(mode.eigenvalue - omega * omega) <= kAtResonance * mode.eigenvalue) {
      // At its own frequency an undamped mode adds nothing finite: unbounded if driven.
      if (drives(mode, load, source_load)) out.resonant_modes.push_back(mode.index);
      continue;
    }
    const std::complex<double> denominator = mode.eigenvalue - omega * omega + i * omega * c;
    if (std::abs(denominator) == 0.0)
      throw NumericalError("modal response: mode " + std::to_string(mode.index) +
                           " has no stiffness at this frequency (rigid-body mode at 0 Hz)");
    out.displacement += phi * (phi.dot(load) / denominator);
  }
  out.unbounded = !out.resonant_modes.empty();
  out.resonant_mode = out.unbounded ? out.resonant_modes.front() : 0;
  // Massless DOFs follow their own loads: x_m += (K_mm + iωC_mm)⁻¹ Q_m.
  if (!modes.condensed.empty()) {
    std::vector<int> m;
    for (const auto& label : modes.condensed) m.push_back(system.index_of(label));
    Eigen::MatrixXcd Dmm(m.size(), m.size());
    Eigen::VectorXcd Qm(m.size());
    for (size_t a = 0; a < m.size(); ++a) {
      Qm(a) = load(m[a]);
      for (size_t b = 0; b < m.size(); ++b)
        Dmm(a, b) = std::complex<double>(system.stiffness(m[a], m[b]), omega * system.damping(m[a], m[b]));
    }
    const Eigen::VectorXcd xm = Dmm.partialPivLu().solve(Qm);
    for (size_t a = 0; a < m.size(); ++a) out.displacement(m[a]) += xm(a);
  }
  return out;
}

}  // namespace railmodal
