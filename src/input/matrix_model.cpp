// M, C and K from Matrix Market files: one model with agreeing sizes and DOF labels, kept
// sparse for ARPACK or made dense for the dense modal solver.
#include <filesystem>
#include <map>

#include "railmodal/errors.hpp"
#include "railmodal/matrix_market.hpp"

namespace railmodal {
namespace {

struct Read {
  std::string path;
  const char* what;  // "mass", "stiffness", "damping"
  MatrixMarketMatrix file;
};

std::string filename(const std::string& path) { return std::filesystem::path(path).filename().string(); }

}  // namespace

Eigen::MatrixXd to_dense(const Eigen::SparseMatrix<double>& matrix) { return Eigen::MatrixXd(matrix); }

MatrixModel load_matrix_model(const std::string& mass_path, const std::string& stiffness_path,
                              const std::string& damping_path) {
  std::vector<Read> reads;
  reads.push_back({mass_path, "mass", read_matrix_market(mass_path, true)});
  reads.push_back({stiffness_path, "stiffness", read_matrix_market(stiffness_path, true)});
  // Damping need not be symmetric (a general viscous matrix is allowed).
  if (!damping_path.empty()) reads.push_back({damping_path, "damping", read_matrix_market(damping_path, false)});

  const Read& first = reads[0];
  const long long n = first.file.matrix.rows();
  const Read* named = nullptr;  // the first file that names DOFs
  for (const Read& r : reads) {
    if (r.file.matrix.rows() != n)
      throw InputError(r.path, r.file.size_line, 1,
                       "the " + std::string(r.what) + " matrix is " + std::to_string(r.file.matrix.rows()) + " × " +
                           std::to_string(r.file.matrix.rows()) + " but the mass matrix (" + first.path + ") is " +
                           std::to_string(n) + " × " + std::to_string(n));
    if (r.file.dof_labels.empty()) continue;
    if (!named) {
      named = &r;
      continue;
    }
    for (long long i = 0; i < n; ++i) {
      const std::string& a = named->file.dof_labels[i];
      const std::string& b = r.file.dof_labels[i];
      if (a != b)
        throw InputError(r.path, r.file.labels_line, 1,
                         "DOF " + std::to_string(i + 1) + " is named '" + b + "' here but '" + a + "' in " +
                             named->path + "; files that name DOFs must name them alike");
    }
  }

  MatrixModel model;
  model.name = filename(mass_path) + ", " + filename(stiffness_path);
  if (!damping_path.empty()) model.name += ", " + filename(damping_path);
  for (long long i = 0; i < n; ++i) {
    const std::string label = named ? named->file.dof_labels[i] : "";
    model.labels.push_back(label.empty() ? "dof" + std::to_string(i + 1) : label);
  }
  // A label a comment gives may be the default label of a DOF no comment names.
  if (named) {
    std::map<std::string, long long> given;  // label → 1-based DOF
    for (long long i = 0; i < n; ++i)
      if (!named->file.dof_labels[i].empty()) given[named->file.dof_labels[i]] = i + 1;
    for (long long i = 0; i < n; ++i) {
      const auto clash = given.find(model.labels[i]);
      if (named->file.dof_labels[i].empty() && clash != given.end())
        throw InputError(named->path, named->file.labels_line, 1,
                         "DOF " + std::to_string(clash->second) + " is named '" + clash->first +
                             "', the default label of DOF " + std::to_string(i + 1) +
                             ", which no comment names; name that DOF too or choose another label");
    }
  }
  // A general file was checked symmetric to round-off; make it exact for the symmetric solver.
  const auto symmetric = [](const Eigen::SparseMatrix<double>& A) -> Eigen::SparseMatrix<double> {
    return 0.5 * (A + Eigen::SparseMatrix<double>(A.transpose()));
  };
  model.mass = reads[0].file.symmetric_storage ? reads[0].file.matrix : symmetric(reads[0].file.matrix);
  model.stiffness = reads[1].file.symmetric_storage ? reads[1].file.matrix : symmetric(reads[1].file.matrix);
  if (reads.size() == 3) model.damping = reads[2].file.matrix;
  else model.damping.resize(static_cast<int>(n), static_cast<int>(n));
  return model;
}

SparseSystem to_sparse_system(const MatrixModel& model) {
  SparseSystem system;
  system.name = model.name;
  for (const auto& label : model.labels) {
    Dof dof;
    dof.label = label;
    dof.body = -1;  // no bodies: modes are named after DOFs (solve/mode_naming.cpp)
    system.dofs.push_back(dof);
  }
  system.mass = model.mass;
  system.damping = model.damping;
  system.stiffness = model.stiffness;
  return system;
}

LinearSystem to_linear_system(const MatrixModel& model) { return to_linear_system(to_sparse_system(model)); }

}  // namespace railmodal
