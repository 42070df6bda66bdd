#include "model/spring_formulas.hpp"

#include <cmath>

namespace railmodal::model {

double coil_spring_stiffness(double wire_diameter, double mean_radius, double active_coils,
                             double shear_modulus) {
  // eq. (4): f = 64 P n r³ / (δ⁴ G)
  return std::pow(wire_diameter, 4) * shear_modulus /
         (64.0 * active_coils * std::pow(mean_radius, 3));
}

double leaf_spring_deflection(const LeafSpringGeometry& leaf, double load) {
  const double l = leaf.length / 2.0;  // the book's l is half the spring length
  const double P = load / 2.0;         // and P the load on one end
  const double n = leaf.leaves;
  const double section = n * leaf.leaf_width * std::pow(leaf.leaf_thickness, 3) * leaf.modulus;
  const double tg = std::tan(leaf.shackle_inclination);
  // eq. (92a); with α = 0 it is Wittig's 6 P l³ / (n b h³ E), eq. (26).
  const double bending = 6.0 * P * l * l * (l + leaf.free_camber * tg) / (section + 6.0 * P * l * l * tg);
  // eq. (26)/(93): the full-length leaves stiffen the spring by 2n/(2n + n₁).
  return bending * 2.0 * n / (2.0 * n + leaf.full_length_leaves);
}

double leaf_spring_stiffness(const LeafSpringGeometry& leaf, double load) {
  // With vertical shackles the spring is linear: any load gives the same ratio.
  const double at = leaf.shackle_inclination == 0.0 ? 1.0 : load;
  return at / leaf_spring_deflection(leaf, at);
}

double leaf_spring_relative_friction(const LeafSpringGeometry& leaf, double leaf_on_leaf_friction) {
  const double n = leaf.leaves;
  return leaf_on_leaf_friction * (n - 1.0) * (n + 0.5 * leaf.full_length_leaves) * leaf.leaf_thickness /
         (n * leaf.length / 2.0);
}

double elliptic_spring_stiffness(double length, double leaf_width, double leaf_thickness,
                                 int leaves, int rows, double modulus) {
  const double l = length / 2.0;
  return rows * leaves * leaf_width * std::pow(leaf_thickness, 3) * modulus / (6.0 * std::pow(l, 3));
}

}  // namespace railmodal::model
