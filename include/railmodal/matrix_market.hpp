// railmodal — mass, damping and stiffness matrices from Matrix Market files, the exchange
// format finite-element tools export (https://math.nist.gov/MatrixMarket/formats.html).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::MatrixModel model =
//         railmodal::load_matrix_model("data/matrices/resort_car_vertical_M.mtx",
//                                      "data/matrices/resort_car_vertical_K.mtx");
//     railmodal::LinearSystem system = railmodal::to_linear_system(model);  // dense
//     railmodal::ModalResult result = railmodal::solve_modes(system);
//     // or, for a large model, sparse end to end: solve_modes(to_sparse_system(model), options)
//     for (const auto& mode : result.modes) std::cout << mode.name << "  " << mode.frequency_hz << "\n";
//   }
//
// Accepted: `%%MatrixMarket matrix coordinate|array real|integer general|symmetric`,
// square. Symmetric files store the lower triangle (i ≥ j), which is mirrored; duplicate
// coordinate entries are summed. Comments may name the degrees of freedom:
//
//   % railmodal dofs: body.bounce body.pitch bogie1.bounce
//   % railmodal dof 4 bogie2.bounce
//
// docs/input.md describes the format and every error.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <ostream>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/sparse_system.hpp"

namespace railmodal {

/// One matrix read from a Matrix Market file.
struct MatrixMarketMatrix {
  Eigen::SparseMatrix<double> matrix;  ///< square, the full matrix (a symmetric file mirrored)
  /// The DOF labels the file's `% railmodal` comments name: empty when none, else one per
  /// row with "" for a row no comment names.
  std::vector<std::string> dof_labels;
  bool symmetric_storage = false;  ///< the banner said `symmetric`
  int size_line = 0;               ///< line of the size line (for messages about the size)
  int labels_line = 0;             ///< first line naming a DOF, 0 if none
};

/// Reads one file. Throws InputError ("file:line:col: error: ...") for a missing or bad
/// banner, an unsupported field (pattern, complex) or symmetry (hermitian, skew-symmetric),
/// a matrix that is not square, a malformed size line, an index out of range, an entry above
/// the diagonal of a symmetric file, too few or too many entries, a value that is not a
/// finite number, bytes that are not UTF-8 text, and a malformed `% railmodal` comment.
/// With require_symmetric, a `general` file must hold a symmetric matrix:
/// |aᵢⱼ − aⱼᵢ| ≤ 1e-10·max(|aᵢⱼ|, |aⱼᵢ|) + 1e-14·maxₖₗ|aₖₗ|, else an InputError at the
/// first entry in file order whose mirror differs.
MatrixMarketMatrix read_matrix_market(const std::string& path, bool require_symmetric = false);

/// Writes `matrix` in coordinate real format with 17 significant digits (exact round trip).
/// symmetric: only the lower triangle, banner `symmetric` (the caller vouches for the
/// symmetry). Non-empty labels (one per row) are written as `% railmodal dofs:` comments.
void write_matrix_market(std::ostream& out, const Eigen::SparseMatrix<double>& matrix, bool symmetric,
                         const std::vector<std::string>& dof_labels = {});

/// The dense copy of a sparse matrix (the dense modal solver's input).
Eigen::MatrixXd to_dense(const Eigen::SparseMatrix<double>& matrix);

/// M, C and K read from files: a linear system without bodies. Kept sparse so that large
/// models need not be densified.
struct MatrixModel {
  std::string name;                 ///< "M.mtx, K.mtx[, C.mtx]" (file names, for reports)
  std::vector<std::string> labels;  ///< one per DOF: named by the files, else "dof1", "dof2", ...
  Eigen::SparseMatrix<double> mass;
  Eigen::SparseMatrix<double> damping;  ///< zero when no damping file is given
  Eigen::SparseMatrix<double> stiffness;
};

/// Reads M and K (and C when damping_path is not empty). M and K must be symmetric; all
/// must have the same size, and files that name DOFs must name them alike (an InputError
/// naming both files otherwise). DOF labels come from the first file that names them
/// (mass, stiffness, damping); a DOF no file names is "dof<i>" (1-based).
MatrixModel load_matrix_model(const std::string& mass_path, const std::string& stiffness_path,
                              const std::string& damping_path = "");

/// The model kept sparse, for ARPACK (DOF labels from the files, Dof::body -1).
SparseSystem to_sparse_system(const MatrixModel& model);

/// The dense LinearSystem of a MatrixModel: no vehicle bodies (Dof::body is -1), no
/// gravity stiffness, no track inputs. Modes are named after the DOF holding the most
/// kinetic energy.
LinearSystem to_linear_system(const MatrixModel& model);

}  // namespace railmodal
