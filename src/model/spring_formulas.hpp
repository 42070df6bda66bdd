// Spring stiffness from spring geometry (springs digest §2.2–2.6). SI in, N/m out.
#pragma once

namespace railmodal::model {

/// Round-bar cylindrical coil spring, Kreissig eq. (4): f = 64 P n r³/(δ⁴ G), so
/// c = δ⁴ G / (64 n r³).
double coil_spring_stiffness(double wire_diameter, double mean_radius, double active_coils,
                             double shear_modulus);

/// Geometry of a laminated (leaf) spring.
struct LeafSpringGeometry {
  double length = 0.0;        ///< 2l, eye to eye, m
  double leaf_width = 0.0;    ///< b, m
  double leaf_thickness = 0.0;  ///< h, m
  int leaves = 0;             ///< n
  int full_length_leaves = 0;   ///< n₁, "prismatic" (main) leaves
  double modulus = 0.0;       ///< E, Pa
  double free_camber = 0.0;   ///< f_φ, factory camber, m (only with inclined shackles)
  double shackle_inclination = 0.0;  ///< α, rad, 0 for vertical shackles
};

/// Static deflection of a leaf spring under the whole spring load `load` (2P, N):
/// Wittig eq. (26) for vertical shackles, eq. (92a) for shackles inclined at α, both with
/// the effective-deflection factor 2n/(2n + n₁) of eqs. (26)/(93).
double leaf_spring_deflection(const LeafSpringGeometry& leaf, double load);

/// Secant stiffness load / deflection of a leaf spring at its static load (N/m). With
/// vertical shackles the spring is linear and the load cancels.
double leaf_spring_stiffness(const LeafSpringGeometry& leaf, double load);

/// Marié's relative friction coefficient of a leaf spring, eq. (34):
/// φ = ψ (n − 1)(n + 0.5 n₁) h / (n l), ψ the leaf-on-leaf friction coefficient, l half the
/// spring length (springs digest §2.3).
double leaf_spring_relative_friction(const LeafSpringGeometry& leaf, double leaf_on_leaf_friction);

/// Galakhov elliptic spring set, bogie-wagons-natural digest §4 Ex. 2: f = 12 P l³/(A n b h³ E)
/// with P half the set load, so c = A n b h³ E / (6 l³); l is half the spring length.
double elliptic_spring_stiffness(double length, double leaf_width, double leaf_thickness,
                                 int leaves, int rows, double modulus);

}  // namespace railmodal::model
