// One step of the Dormand–Prince 5(4) Runge–Kutta pair (Dormand & Prince 1980; the method of
// MATLAB's ode45 and scipy's RK45): the fifth-order solution and an embedded fourth-order
// error estimate from seven stages.
#pragma once

#include <Eigen/Core>

namespace railmodal::simulate {

struct DormandPrinceStep {
  Eigen::VectorXd y;      ///< fifth-order solution at t + h
  Eigen::VectorXd error;  ///< fifth minus fourth order: the local error estimate
};

/// f(t, y, &dy) evaluates the right-hand side.
template <class Rhs>
DormandPrinceStep dormand_prince_step(const Rhs& f, double t, const Eigen::VectorXd& y, double h) {
  static constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  static constexpr double a21 = 1.0 / 5;
  static constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  static constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  static constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
  static constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                          a65 = -5103.0 / 18656;
  static constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  // fifth minus fourth order weights
  static constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                          e6 = 22.0 / 525, e7 = -1.0 / 40;
  const Eigen::Index n = y.size();
  Eigen::VectorXd k1(n), k2(n), k3(n), k4(n), k5(n), k6(n), k7(n);
  f(t, y, &k1);
  f(t + c2 * h, y + h * (a21 * k1), &k2);
  f(t + c3 * h, y + h * (a31 * k1 + a32 * k2), &k3);
  f(t + c4 * h, y + h * (a41 * k1 + a42 * k2 + a43 * k3), &k4);
  f(t + c5 * h, y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4), &k5);
  f(t + h, y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5), &k6);
  DormandPrinceStep s;
  s.y = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
  f(t + h, s.y, &k7);
  s.error = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
  return s;
}

}  // namespace railmodal::simulate
