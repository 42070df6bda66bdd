// The suspension elements a nonlinear simulation follows beyond the linear model: leaf springs
// with friction and progressive springs, each with its kinematics and its static state.
#pragma once

#include <Eigen/Core>
#include <complex>
#include <optional>
#include <vector>

#include "railmodal/excitation.hpp"
#include "railmodal/simulation.hpp"

namespace railmodal::simulate {

/// One harmonic of the track's vertical displacement under an element (up positive):
/// u(t) = Re(amplitude · e^{iω(t − delay)}).
struct TrackHarmonic {
  std::complex<double> amplitude;
  double omega = 0.0;
  double delay = 0.0;
};

struct NonlinearElement {
  int element = 0;            ///< index into Vehicle::elements
  Eigen::RowVectorXd stretch;  ///< vertical stretch (up) per DOF; compression δ = −(stretch·x − u)
  double static_load = 0.0;   ///< P0, N, compression positive
  double tangent = 0.0;       ///< c0, N/m: what the linear stiffness matrix holds for the element
  double friction = 0.0;      ///< φ; 0 when leaf friction is not simulated for it
  std::optional<LoadDeflectionCurve> curve;  ///< per spring; followed when progressive springs are
  int springs = 1;                           ///< springs in parallel on the curve
  double static_deflection = 0.0;            ///< on the curve under P0
  std::vector<TrackHarmonic> track;          ///< empty for an element between two bodies

  /// Elastic reaction (N, compression positive) at the dynamic compression δ from equilibrium.
  double reaction(double delta) const {
    return curve ? springs * curve->load_at(static_deflection + delta) : static_load + tangent * delta;
  }
  /// Track displacement, velocity and acceleration under the element at time t.
  void track_motion(double t, double* u, double* du, double* ddu) const;
};

/// The elements of `system` that carry an effect named in `effects`, with the track harmonics
/// of `loads` under them. Throws std::invalid_argument for a nonlinear stage in series with
/// other stages.
std::vector<NonlinearElement> nonlinear_elements(const LinearSystem& system, const std::vector<HarmonicLoad>& loads,
                                                 const NonlinearEffects& effects);

}  // namespace railmodal::simulate
