// Matrices and complex vectors as JSON, for the timing programs that hand a model to a
// numpy/scipy comparison script (compare_sweep.py, compare_lsim.py, compare_study.py).
#pragma once

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace railmodal::benchmarks {

/// Rows of numbers: numpy.array(json) gives the matrix back.
inline nlohmann::json matrix(const Eigen::MatrixXd& A) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < A.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < A.cols(); ++j) row.push_back(A(i, j));
    rows.push_back(row);
  }
  return rows;
}

/// {"re": [...], "im": [...]}
inline nlohmann::json complex_vector(const Eigen::VectorXcd& v) {
  nlohmann::json re = nlohmann::json::array(), im = nlohmann::json::array();
  for (int i = 0; i < v.size(); ++i) re.push_back(v(i).real()), im.push_back(v(i).imag());
  return {{"re", re}, {"im", im}};
}

}  // namespace railmodal::benchmarks
