// Balancing a real nonsymmetric matrix before its eigenvalues are computed.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace railmodal::solve {

/// Diagonal similarity D⁻¹AD by powers of two that makes each row and column of the
/// off-diagonal part of similar norm (Parlett & Reinsch 1969; LAPACK dgebal without the
/// permutation). Exact in floating point; the eigenvalues are unchanged and an eigenvector x of
/// the balanced matrix is D·x of the original. Returns D; A is overwritten with D⁻¹AD.
inline Eigen::VectorXd balance(Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
  for (bool done = false; !done;) {
    done = true;
    for (int i = 0; i < n; ++i) {
      const double c = A.col(i).cwiseAbs().sum() - std::abs(A(i, i));
      const double r = A.row(i).cwiseAbs().sum() - std::abs(A(i, i));
      if (c == 0.0 || r == 0.0) continue;
      double f = 1.0, cs = c;
      while (cs < r / 2.0) {
        f *= 2.0;
        cs *= 4.0;
      }
      while (cs > r * 2.0) {
        f /= 2.0;
        cs /= 4.0;
      }
      if ((cs + r) / f < 0.95 * (c + r)) {
        done = false;
        d(i) *= f;
        A.row(i) /= f;
        A.col(i) *= f;
      }
    }
  }
  return d;
}

}  // namespace railmodal::solve
