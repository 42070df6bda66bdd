// The low end of a spectrum with a large stiffness or mass contrast (issue 18 item 9): which
// eigenvalues are zero, counted by the inertia of K ∓ tM rather than read off the computed λ,
// and the low eigenvalues to relative accuracy by a Rayleigh–Ritz step whose projected
// matrices are formed in twice the working precision.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace railmodal::solve {

/// Unit round-off of double, 2⁻⁵³.
constexpr double kUnitRoundoff = 0.5 * 2.220446049250313e-16;

/// Half-width t of the band of eigenvalues that are zero to working precision: t = 8·m·ε·d,
/// d = max Σⱼ|Kᵢⱼ|/Mᵢᵢ and m the most nonzeros in a row of K. Storing or factoring K in double
/// perturbs it by |ΔK| ≤ m·ε·|K| row by row, which moves an eigenvalue by about m·ε·d at most
/// (d bounds ‖M^-½|K|M^-½‖ for a diagonal M), so an eigenvalue inside (−t, t) cannot be told
/// from zero and one outside can: a soft spring of 100 N/m beside a 1e15 N/m link between two
/// 1000 kg masses (λ = 0.05 1/s², t = 7e-3 1/s²) is not rigid; beside 1e16 N/m (t = 0.07) it is.
/// t = 1 when K = 0.
double zero_band(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M);
double zero_band(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M);

/// The number of eigenvalues of (K, M) in (−t, t): the negative pivots of an LDLᵀ of K − tM
/// less those of K + tM (Sylvester's law of inertia, M positive definite). Both matrices are
/// nonsingular unless ±t is an eigenvalue, and the count does not depend on how accurately an
/// eigensolver found the eigenvalues. -1 when a factorisation fails.
int eigenvalues_near_zero(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, double t);
int eigenvalues_near_zero(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double t);

/// The bound of the rounding error of an eigenvalue solved in a problem whose largest |λ| is
/// `top`: 4ε·top (a backward-stable solver's error ε·‖M^-½KM^-½‖, with room for the reduction).
/// The dense solver knows `top` (every λ, or those of the refined window); ARPACK, which finds
/// only the lowest, takes max Kᵢᵢ/Mᵢᵢ, a lower bound of λmax of the same order.
inline double rounding_bound(double top) { return 8.0 * kUnitRoundoff * top; }

/// A spectrum whose low end needs refine_low_modes: λ_top/|λ| above 1e8 for its lowest nonzero
/// |λ|, where a direct solve's absolute error ε·λ_top leaves fewer than 8 digits.
bool needs_refinement(const Eigen::VectorXd& values, double top, double zero);

/// Rayleigh–Ritz on the first `count` columns Z of `vectors`: (ZᵀKZ) y = λ (ZᵀMZ) y with ZᵀKZ
/// and ZᵀMZ summed in double-double (error-free products by FMA and sums by TwoSum; Ogita,
/// Rump and Oishi, "Accurate sum and dot product", SIAM J. Sci. Comput. 26 (2005), Dot2).
/// The cancellation that loses a soft spring beside a stiff link (Kz sums terms of 1e15 to
/// 1e2) then costs ε², not ε, and the λ found carry an absolute error of about ε·max|λ| of the
/// window instead of ε·λmax. Replaces values(0..count−1) and the columns by the result.
void refine_low_modes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, int count, Eigen::VectorXd* values,
                      Eigen::MatrixXd* vectors);
void refine_low_modes(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int count,
                      Eigen::VectorXd* values, Eigen::MatrixXd* vectors);

}  // namespace railmodal::solve
