// Moving a force from its plane to the two wheel (counterweight) planes of its axle.
#pragma once

namespace railmodal::gear {

/// The shares of a force acting at `lateral` (m, + right) that the right and left wheel planes
/// at ±S carry, from moments about each plane: right (S + y)/2S, left (S − y)/2S. For a rod
/// plane outside the right wheel at a from it (y = S + a) these are Zhdanov's (2S + a)/2S and
/// −a/2S (eq. (53)–(54), (65)–(66), (73a)–(74a)).
struct PlaneShares {
  double right = 0.0;
  double left = 0.0;
};
inline PlaneShares wheel_plane_shares(double lateral, double half_spacing) {
  return {(half_spacing + lateral) / (2.0 * half_spacing), (half_spacing - lateral) / (2.0 * half_spacing)};
}

}  // namespace railmodal::gear
