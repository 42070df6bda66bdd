#include "ride/ride_march.hpp"

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "railmodal/errors.hpp"

namespace railmodal::ride {
namespace {

// Over a span τ with the input linear from u0 to u1: s(τ) = Φ s(0) + G0 u0 + G1 (u1 − u0),
// Φ = e^{Aτ}, G0 = ∫₀^τ e^{Aσ} dσ B, G1 = (1/τ)∫₀^τ e^{A(τ−σ)} σ dσ B, all three from one
// exponential (Van Loan, "Computing integrals involving the matrix exponential", IEEE TAC 23,
// 1978): exp([[A, B, 0], [0, 0, I/τ], [0, 0, 0]]·τ).
struct Hold {
  Eigen::MatrixXd Phi, G0, G1;
};

Hold hold(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double tau) {
  const int r = static_cast<int>(A.rows()), m = static_cast<int>(B.cols());
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(r + 2 * m, r + 2 * m);
  E.topLeftCorner(r, r) = A * tau;
  E.block(0, r, r, m) = B * tau;
  E.block(r, r + m, m, m).setIdentity();
  const Eigen::MatrixXd X = E.exp();
  Hold out{X.topLeftCorner(r, r), X.block(0, r, r, m), X.block(0, r + m, r, m)};
  if (!out.Phi.allFinite() || !out.G0.allFinite() || !out.G1.allFinite())
    throw NumericalError("ride simulation: the state transition overflowed (an unstable vehicle over this step?)");
  return out;
}

}  // namespace

RideMarch::RideMarch(const RideStateSpace& model, const TrackUnderWheels& track, double speed, double step,
                     double start)
    : track_(track), speed_(speed), h_(step), start_(start) {
  const Eigen::MatrixXd none = Eigen::MatrixXd::Zero(model.A.rows(), 0);
  Phi_ = hold(model.A, none, h_).Phi;
  for (int i = 0; i < track.inputs(); ++i) {
    const Eigen::MatrixXd Bi = model.B.middleCols(3 * i, 3);
    // A sample meets wheel i when start + V t − lag_i is a multiple of Δx, i.e. at
    // t ≡ (lag_i − start)/V modulo m·h, so modulo h as well.
    double delta = std::fmod((track.lag(i) - start) / speed, h_);
    if (delta < 0.0) delta += h_;
    if (delta < 1e-9 * h_ || delta > (1.0 - 1e-9) * h_) delta = 0.0;
    offsets_.push_back(delta);
    if (delta == 0.0) {
      const Hold whole = hold(model.A, Bi, h_);
      P0_.push_back(Eigen::MatrixXd::Zero(Bi.rows(), 3));
      Pd_.push_back(whole.G0 - whole.G1);
      P1_.push_back(whole.G1);
    } else {
      // [0, δ]: from u(t) to u(t+δ); [δ, h]: from u(t+δ) to u(t+h), carried by Φ(h − δ).
      const Hold first = hold(model.A, Bi, delta), second = hold(model.A, Bi, h_ - delta);
      P0_.push_back(second.Phi * (first.G0 - first.G1));
      Pd_.push_back(second.Phi * first.G1 + second.G0 - second.G1);
      P1_.push_back(second.G1);
    }
  }
}

double RideMarch::leading(long k) const { return start_ + speed_ * h_ * static_cast<double>(k);
}

void RideMarch::advance(long k, Eigen::VectorXd* s) {
  next_.noalias() = Phi_ * *s;
  const double t0 = leading(k), t1 = leading(k + 1);
  for (int i = 0; i < track_.inputs(); ++i) {
    next_.noalias() += P0_[i] * track_.displacement_of(i, t0);
    next_.noalias() += Pd_[i] * track_.displacement_of(i, t0 + speed_ * offsets_[i]);
    next_.noalias() += P1_[i] * track_.displacement_of(i, t1);
  }
  s->swap(next_);
}

Eigen::MatrixXd RideMarch::transition_power(long count) const {
  Eigen::MatrixXd result = Eigen::MatrixXd::Identity(Phi_.rows(), Phi_.cols()), base = Phi_;
  for (; count > 0; count >>= 1) {
    if (count & 1) result = result * base;
    base = base * base;
  }
  return result;
}

}  // namespace railmodal::ride
