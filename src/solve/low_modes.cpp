// Rigid-body modes by inertia and low eigenvalues to relative accuracy beside stiff links.
#include "solve/low_modes.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

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

// zero_band from d = max Σⱼ|Kᵢⱼ|/Mᵢᵢ and the most nonzeros in a row of K.
double band_of(double d, int most) {
  if (!(d > 0.0)) return 1.0;  // K = 0: every eigenvalue is exactly zero; any t > 0 counts them
  return 8.0 * most * 2.0 * kUnitRoundoff * d;
}

// band_of for a sparse K: its entries visited column by column, summed per row.
double band(const SparseMatrix& K, const SparseMatrix& M) {
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
  return band_of(d, *std::max_element(row_count.begin(), row_count.end()));
}

int negative_pivots(const Eigen::MatrixXd& A) {
  // This thread's factorisation, its storage kept between calls (two per dense modal solve,
  // one solve per variant of a study): the same factorisation of the same matrix.
  thread_local Eigen::LDLT<Eigen::MatrixXd> ldlt;
  ldlt.compute(A);
  if (ldlt.info() != Eigen::Success || !ldlt.vectorD().allFinite()) return -1;
  return static_cast<int>((ldlt.vectorD().array() < 0.0).count());
}

int negative_pivots(const SparseMatrix& A) {
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);  // AMD ordering
  if (ldlt.info() != Eigen::Success || !ldlt.vectorD().allFinite()) return -1;
  return static_cast<int>((ldlt.vectorD().array() < 0.0).count());
}

template <class Matrix>
int near_zero(const Matrix& K, const Matrix& M, double t) {
  const Matrix below = K - t * M, above = K + t * M;
  const int low = negative_pivots(below), high = negative_pivots(above);
  return low < 0 || high < 0 ? -1 : low - high;
}

}  // namespace

double zero_band(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  // Row by row, without the sparse version's lists (each row's sum in the same order of j as
  // a column-by-column visit, so the same d).
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
  return band_of(d, most);
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
