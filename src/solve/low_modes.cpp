// Rigid-body modes by inertia and low eigenvalues to relative accuracy beside stiff links.
#include "solve/low_modes.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

namespace railmodal::solve {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// Every nonzero K(i, j) of a dense or a sparse matrix, as f(i, j, K(i, j)).
template <class F>
void for_each_entry(const Eigen::MatrixXd& K, F f) {
  for (Eigen::Index j = 0; j < K.cols(); ++j)
    for (Eigen::Index i = 0; i < K.rows(); ++i)
      if (K(i, j) != 0.0) f(i, j, K(i, j));
}

template <class F>
void for_each_entry(const SparseMatrix& K, F f) {
  for (Eigen::Index j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.value() != 0.0) f(it.row(), it.col(), it.value());
}

// A sum hi + lo of products, each added without error (Dot2 of Ogita, Rump and Oishi 2005:
// TwoProduct by FMA, TwoSum), so that it is as accurate as if summed in twice the precision.
struct CompensatedSum {
  double hi = 0.0, lo = 0.0;
  void add_product(double a, double b) {
    const double p = a * b;
    const double p_error = std::fma(a, b, -p);
    const double s = hi + p;
    const double z = s - hi;
    lo += ((hi - (s - z)) + (p - z)) + p_error;
    hi = s;
  }
  double value() const { return hi + lo; }
};

// ZᵀAZ, summed in double-double: A Z first (kept as hi + lo), then Zᵀ times it.
template <class Matrix>
Eigen::MatrixXd compensated_projection(const Matrix& A, const Eigen::MatrixXd& Z) {
  const Eigen::Index n = Z.rows(), w = Z.cols();
  std::vector<CompensatedSum> AZ(static_cast<size_t>(n * w));
  for_each_entry(A, [&](Eigen::Index i, Eigen::Index j, double a) {
    for (Eigen::Index c = 0; c < w; ++c) AZ[static_cast<size_t>(c * n + i)].add_product(a, Z(j, c));
  });
  Eigen::MatrixXd P(w, w);
  for (Eigen::Index c = 0; c < w; ++c)
    for (Eigen::Index d = c; d < w; ++d) {
      CompensatedSum s;
      for (Eigen::Index i = 0; i < n; ++i) {
        const CompensatedSum& a = AZ[static_cast<size_t>(d * n + i)];
        s.add_product(Z(i, c), a.hi);
        s.add_product(Z(i, c), a.lo);
      }
      P(c, d) = P(d, c) = s.value();
    }
  return P;
}

template <class Matrix>
void refine(const Matrix& K, const Matrix& M, int count, Eigen::VectorXd* values, Eigen::MatrixXd* vectors) {
  if (count < 1) return;
  const Eigen::MatrixXd Z = vectors->leftCols(count);
  const Eigen::MatrixXd A = compensated_projection(K, Z), B = compensated_projection(M, Z);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rr(A, B);
  if (rr.info() != Eigen::Success) return;  // Z not independent in M: keep what the solver gave
  values->head(count) = rr.eigenvalues();
  vectors->leftCols(count) = Z * rr.eigenvectors();
}

// d = max Σⱼ|Kᵢⱼ|/Mᵢᵢ and m = the most nonzeros in a row of K, for zero_band.
template <class Matrix>
double band(const Matrix& K, const Matrix& M) {
  const Eigen::VectorXd m = M.diagonal();
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(K.rows());
  std::vector<int> row_count(static_cast<size_t>(K.rows()), 0);
  for_each_entry(K, [&](Eigen::Index i, Eigen::Index, double k) {
    row_sum(i) += std::abs(k);
    ++row_count[static_cast<size_t>(i)];
  });
  double d = 0.0;
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (m(i) > 0.0) d = std::max(d, row_sum(i) / m(i));
  if (!(d > 0.0)) return 1.0;  // K = 0: every eigenvalue is exactly zero; any t > 0 counts them
  const int most = *std::max_element(row_count.begin(), row_count.end());
  return 8.0 * most * 2.0 * kUnitRoundoff * d;
}

// The negative pivots of an LDLᵀ of the lower triangle of the n × n column-major matrix `a`,
// factored in place: Eigen 3.4's LDLT (ldlt_inplace<Lower>::unblocked) written out for the
// small dense matrices of a modal solve, the same operations in the same order, so the same
// pivots to the bit (Crout order; each step pivots on the largest |diagonal entry| left as it
// stands before its own update, the first one on ties; its matrix-vector products' sums).
// At 6 × 6, twice per modal solve and so twice per variant of a study, Eigen's LDLT with the
// matrices K ∓ tM it is given cost 3.3 k instructions a factorisation, this 2.4 k. -1 where
// Eigen's reports a failure (a zero pivot followed by a nonzero one, an entire zero diagonal
// with entries off it) or a pivot is not finite.
int negative_pivots_in_place(double* a, int n) {
  const auto at = [a, n](int i, int j) -> double& { return a[static_cast<size_t>(j) * n + i]; };
  if (n == 1) return !std::isfinite(at(0, 0)) ? -1 : at(0, 0) < 0.0 ? 1 : 0;  // Eigen's 1 × 1 case
  thread_local std::vector<double> scaled;  // D(j)·L(k, j), j < k: this thread's, kept
  scaled.resize(static_cast<size_t>(n));
  bool found_zero_pivot = false, ok = true;
  for (int k = 0; k < n; ++k) {
    int biggest = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(at(i, i)) > std::abs(at(biggest, biggest))) biggest = i;
    if (biggest != k) {  // the symmetric swap of rows and columns k and biggest, lower part only
      for (int j = 0; j < k; ++j) std::swap(at(k, j), at(biggest, j));
      for (int i = biggest + 1; i < n; ++i) std::swap(at(i, k), at(i, biggest));
      std::swap(at(k, k), at(biggest, biggest));
      for (int i = k + 1; i < biggest; ++i) std::swap(at(i, k), at(biggest, i));
    }
    if (k > 0) {
      for (int j = 0; j < k; ++j) scaled[j] = at(j, j) * at(k, j);
      double dot = at(k, 0) * scaled[0];
      for (int j = 1; j < k; ++j) dot += at(k, j) * scaled[j];
      at(k, k) -= dot;
      // Column k below the pivot less L(i, 0..k−1)·scaled: Eigen's matrix-vector product sums
      // 16 columns at a time from k = 128 on (4 from 4000 rows on), a lone row in one sum.
      const int rows_below = n - k - 1;
      const int block = k < 128 || rows_below == 1 ? k : (n * 8 < 32000 ? 16 : 4);
      for (int j0 = 0; j0 < k; j0 += block) {
        const int j1 = std::min(k, j0 + block);
        for (int i = k + 1; i < n; ++i) {
          double sum = 0.0;
          for (int j = j0; j < j1; ++j) sum += at(i, j) * scaled[j];
          at(i, k) += -1.0 * sum;
        }
      }
    }
    const double pivot = at(k, k);
    const bool valid = std::abs(pivot) > 0.0;
    if (k == 0 && !valid) {  // the whole diagonal is zero: LDLᵀ of the zero matrix only
      for (int j = 0; j < n; ++j)
        for (int i = j + 1; i < n; ++i)
          if (at(i, j) != 0.0) return -1;
      return 0;
    }
    for (int i = k + 1; i < n; ++i) {
      if (valid) at(i, k) /= pivot;
      else if (at(i, k) != 0.0) ok = false;
    }
    if (found_zero_pivot && valid) ok = false;
    else if (!valid) found_zero_pivot = true;
  }
  int negative = 0;
  for (int k = 0; k < n; ++k) {
    if (!std::isfinite(at(k, k))) return -1;
    if (at(k, k) < 0.0) ++negative;
  }
  return ok ? negative : -1;
}

int negative_pivots(const SparseMatrix& A) {
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);  // AMD ordering
  if (ldlt.info() != Eigen::Success || !ldlt.vectorD().allFinite()) return -1;
  return static_cast<int>((ldlt.vectorD().array() < 0.0).count());
}

int near_zero(const SparseMatrix& K, const SparseMatrix& M, double t) {
  const SparseMatrix below = K - t * M, above = K + t * M;
  const int low = negative_pivots(below), high = negative_pivots(above);
  return low < 0 || high < 0 ? -1 : low - high;
}

// The negative pivots of K + s·M (s = ∓t), its lower triangle formed in this thread's kept
// storage (the entries K(i, j) + s·M(i, j) of Eigen's K ∓ t·M, rounded the same way).
int negative_pivots_of_sum(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, double s) {
  thread_local std::vector<double> work;
  const int n = static_cast<int>(K.rows());
  work.resize(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i) work[static_cast<size_t>(j) * n + i] = K(i, j) + s * M(i, j);
  return negative_pivots_in_place(work.data(), n);
}

int near_zero(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, double t) {
  const int low = negative_pivots_of_sum(K, M, -t), high = negative_pivots_of_sum(K, M, t);
  return low < 0 || high < 0 ? -1 : low - high;
}

}  // namespace

double zero_band(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  // band() row by row, without its lists (each row's sum in the same order of j, so the same d).
  double d = 0.0;
  int most = 0;
  for (Eigen::Index i = 0; i < K.rows(); ++i) {
    double row_sum = 0.0;
    int row_count = 0;
    for (Eigen::Index j = 0; j < K.cols(); ++j)
      if (K(i, j) != 0.0) row_sum += std::abs(K(i, j)), ++row_count;
    most = std::max(most, row_count);
    if (M(i, i) > 0.0) d = std::max(d, row_sum / M(i, i));
  }
  if (!(d > 0.0)) return 1.0;  // K = 0: every eigenvalue is exactly zero; any t > 0 counts them
  return 8.0 * most * 2.0 * kUnitRoundoff * d;
}
double zero_band(const SparseMatrix& K, const SparseMatrix& M) { return band(K, M); }

int eigenvalues_near_zero(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, double t) { return near_zero(K, M, t); }
int eigenvalues_near_zero(const SparseMatrix& K, const SparseMatrix& M, double t) { return near_zero(K, M, t); }

bool needs_refinement(const Eigen::VectorXd& values, double top, double zero) {
  for (Eigen::Index k = 0; k < values.size(); ++k)
    if (std::abs(values(k)) > zero && top > 1e8 * std::abs(values(k))) return true;
  return false;
}

void refine_low_modes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, int count, Eigen::VectorXd* values,
                      Eigen::MatrixXd* vectors) {
  refine(K, M, count, values, vectors);
}

void refine_low_modes(const SparseMatrix& K, const SparseMatrix& M, int count, Eigen::VectorXd* values,
                      Eigen::MatrixXd* vectors) {
  refine(K, M, count, values, vectors);
}

}  // namespace railmodal::solve
