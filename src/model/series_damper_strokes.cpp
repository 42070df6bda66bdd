#include "model/series_damper_strokes.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace railmodal::model {
namespace {

Eigen::MatrixXd with_zero_border(const Eigen::MatrixXd& A, Eigen::Index rows, Eigen::Index cols) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(rows, cols);
  out.topLeftCorner(A.rows(), A.cols()) = A;
  return out;
}

void check_series_damper(const LinearSystem& system, const SeriesDamperRow& row) {
  const std::string name = row.element >= 0 && row.element < static_cast<int>(system.vehicle.elements.size())
                               ? system.vehicle.elements[static_cast<size_t>(row.element)].name
                               : std::to_string(row.element);
  if (row.stretch.size() != system.size())
    throw std::invalid_argument("series damper of element '" + name + "': " + std::to_string(row.stretch.size()) +
                                " stretch entries, the system has " + std::to_string(system.size()) +
                                " degrees of freedom");
  if (!(row.damping > 0.0 && row.stiffness > 0.0 && std::isfinite(row.damping) && std::isfinite(row.stiffness)))
    throw std::invalid_argument("series damper of element '" + name +
                                "': its damping and series stiffness must be positive and finite");
}

}  // namespace

LinearSystem with_series_damper_strokes(const LinearSystem& system) {
  const Eigen::Index n = system.size(), m = static_cast<Eigen::Index>(system.series_dampers.size());
  LinearSystem out = system;
  out.series_dampers.clear();
  if (m == 0) return out;
  const Eigen::Index total = n + m;
  out.mass = with_zero_border(system.mass, total, total);
  out.damping = with_zero_border(system.damping.size() == 0 ? Eigen::MatrixXd::Zero(n, n) : system.damping, total, total);
  out.stiffness = with_zero_border(system.stiffness, total, total);
  out.gravity_stiffness =
      with_zero_border(system.gravity_stiffness.size() == 0 ? Eigen::MatrixXd::Zero(n, n) : system.gravity_stiffness, total, total);
  if (system.element_vertical_map.size() > 0)
    out.element_vertical_map = with_zero_border(system.element_vertical_map, system.element_vertical_map.rows(), total);
  for (TrackInput& t : out.track_inputs) {
    t.load_per_displacement = with_zero_border(t.load_per_displacement, total, 3);
    t.load_per_velocity = with_zero_border(t.load_per_velocity, total, 3);
  }
  for (Eigen::Index j = 0; j < m; ++j) {
    const SeriesDamperRow& row = system.series_dampers[static_cast<size_t>(j)];
    check_series_damper(system, row);
    const Eigen::Index u = n + j;
    out.stiffness.topLeftCorner(n, n).noalias() += row.stiffness * row.stretch.transpose() * row.stretch;
    out.stiffness.block(0, u, n, 1) = -row.stiffness * row.stretch.transpose();
    out.stiffness.block(u, 0, 1, n) = -row.stiffness * row.stretch;
    out.stiffness(u, u) = row.stiffness;
    out.damping(u, u) = row.damping;
    const std::string element = row.element >= 0 && row.element < static_cast<int>(system.vehicle.elements.size())
                                    ? system.vehicle.elements[static_cast<size_t>(row.element)].name
                                    : "series damper " + std::to_string(j + 1);
    out.dofs.push_back({element + "." + to_string(row.direction) + " stroke", -1, row.direction});
  }
  return out;
}

Eigen::MatrixXd stroke_followers(const LinearSystem& system) {
  Eigen::MatrixXd S(static_cast<Eigen::Index>(system.series_dampers.size()), system.size());
  for (size_t j = 0; j < system.series_dampers.size(); ++j) {
    check_series_damper(system, system.series_dampers[j]);
    S.row(static_cast<Eigen::Index>(j)) = system.series_dampers[j].stretch;
  }
  return S;
}

}  // namespace railmodal::model
