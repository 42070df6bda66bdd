// Kalker's creep coefficients f11, f22, f23, f33 of one contact ellipse.
#include <cmath>
#include <stdexcept>
#include <string>

#include "railmodal/wheel_rail.hpp"
#include "shortest_text.hpp"

namespace railmodal {

CreepCoefficients creep_coefficients(const HertzContact& ellipse, double youngs_modulus, double poisson_ratio) {
  if (!(std::isfinite(ellipse.a) && ellipse.a > 0.0 && std::isfinite(ellipse.b) && ellipse.b > 0.0))
    throw std::invalid_argument("creep_coefficients: the ellipse's semi-axes must be positive and finite (a = " +
                                shortest_text(ellipse.a, 6) + " m, b = " + shortest_text(ellipse.b, 6) + " m)");
  if (!(std::isfinite(youngs_modulus) && youngs_modulus > 0.0))
    throw std::invalid_argument("creep_coefficients: Young's modulus must be positive and finite, not " +
                                shortest_text(youngs_modulus));
  // kalker_coefficients checks a/b and ν against the table.
  const KalkerCoefficients c = kalker_coefficients(ellipse.a / ellipse.b, poisson_ratio);

  // Kalker's linear theory (1967; 1990, Appendix E): with c² = ab the area scale and G the shear
  // modulus, F_x = −G c² C11 ξ_x, F_y = −G c² C22 ξ_y − G c³ C23 φ, M_z = G c³ C23 ξ_y − G c⁴ C33 φ,
  // φ the spin creepage (1/m). These are the f's of CreepCoefficients with its signs.
  const double shear_modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  const double area = ellipse.a * ellipse.b;  // c²
  CreepCoefficients f;
  f.f11 = shear_modulus * area * c.c11;
  f.f22 = shear_modulus * area * c.c22;
  f.f23 = shear_modulus * std::pow(area, 1.5) * c.c23;
  f.f33 = shear_modulus * area * area * c.c33;
  return f;
}

}  // namespace railmodal
