// Degrees of freedom named from Python: by label ("body.bounce") or by index, checked against
// the system, with a ValueError that lists the labels there are.
#pragma once

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal::python {

inline std::vector<std::string> dof_labels(const std::vector<Dof>& dofs) {
  std::vector<std::string> labels;
  labels.reserve(dofs.size());
  for (const Dof& d : dofs) labels.push_back(d.label);
  return labels;
}

/// The index of a DOF given as a label or an int (negative ints count from the end, as numpy's).
inline int dof_index(const LinearSystem& system, pybind11::handle dof) {
  if (pybind11::isinstance<pybind11::str>(dof)) {
    const std::string label = dof.cast<std::string>();
    const int i = system.index_of(label);
    if (i >= 0) return i;
    std::string known;
    for (const Dof& d : system.dofs) known += (known.empty() ? "" : ", ") + d.label;
    throw pybind11::value_error("no degree of freedom '" + label + "' (there are: " + known + ")");
  }
  int i = dof.cast<int>();
  if (i < 0) i += system.size();
  if (i < 0 || i >= system.size())
    throw pybind11::value_error("degree of freedom " + std::to_string(dof.cast<int>()) + " out of range (" +
                                std::to_string(system.size()) + " of them)");
  return i;
}

/// A LinearSystem from dense M, K (and C), DOFs labelled dof1, dof2, ... unless `labels` name
/// them (bind_model.cpp). ValueError for matrices that are not square, alike and finite.
LinearSystem system_from_arrays(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness,
                                const std::optional<Eigen::MatrixXd>& damping, const std::vector<std::string>& labels);

}  // namespace railmodal::python
