// Matrix Market writer: what the reader reads back exactly (17 significant digits), so
// that assembled wagons can be handed to other tools (scipy, FE packages) and back.
#include <iomanip>
#include <stdexcept>

#include "railmodal/matrix_market.hpp"

namespace railmodal {

void write_matrix_market(std::ostream& out, const Eigen::SparseMatrix<double>& matrix, bool symmetric,
                         const std::vector<std::string>& dof_labels) {
  if (matrix.rows() != matrix.cols()) throw std::invalid_argument("write_matrix_market: the matrix is not square");
  if (!dof_labels.empty() && static_cast<long long>(dof_labels.size()) != matrix.rows())
    throw std::invalid_argument("write_matrix_market: dof_labels must be empty or one per row");
  // Column by column (the storage order), the lower triangle only when symmetric.
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < matrix.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, k); it; ++it)
      if (!symmetric || it.row() >= it.col()) entries.emplace_back(it.row(), it.col(), it.value());
  out << "%%MatrixMarket matrix coordinate real " << (symmetric ? "symmetric" : "general") << "\n";
  // One label list per line keeps lines short for large models.
  constexpr size_t kPerLine = 8;
  for (size_t i = 0; i < dof_labels.size(); i += kPerLine) {
    out << "% railmodal dofs:";
    for (size_t j = i; j < std::min(i + kPerLine, dof_labels.size()); ++j) out << " " << dof_labels[j];
    out << "\n";
  }
  out << matrix.rows() << " " << matrix.cols() << " " << entries.size() << "\n";
  out << std::setprecision(17);
  for (const auto& e : entries) out << e.row() + 1 << " " << e.col() + 1 << " " << e.value() << "\n";
}

}  // namespace railmodal
