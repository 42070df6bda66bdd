// Fourier series of a train of local dips (rail joints, wheel flats), in closed form.
#include <cmath>
#include <stdexcept>

#include "railmodal/excitation.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;

// sin(x)/x, exact at and near 0.
double sinc(double x) { return std::abs(x) < 1e-8 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

// (sin u − u cos u)/u³, by its series where the difference cancels.
double parabola_kernel(double u) {
  if (std::abs(u) < 1e-2) return 1.0 / 3.0 - u * u / 30.0 + u * u * u * u / 840.0;
  return (std::sin(u) - u * std::cos(u)) / (u * u * u);
}

}  // namespace

const char* to_string(DipShape shape) {
  switch (shape) {
    case DipShape::cosine: return "cosine";
    case DipShape::triangular: return "triangular";
    case DipShape::parabolic: return "parabolic";
  }
  return "?";
}

std::optional<DipShape> dip_shape_from_string(const std::string& word) {
  for (DipShape s : {DipShape::cosine, DipShape::triangular, DipShape::parabolic})
    if (word == to_string(s)) return s;
  return std::nullopt;
}

double dip_harmonic(DipShape shape, double depth, double length, double period, int k) {
  if (!(period > 0.0) || !(length > 0.0) || length > period * (1.0 + 1e-12) || k < 1)
    throw std::invalid_argument("dip_harmonic: need 0 < length ≤ period and k ≥ 1");
  // A_k = (2/period) ∫_{−l/2}^{l/2} −η(s) cos(βs) ds, β = 2πk/period (η is even).
  const double beta = 2.0 * kPi * k / period;
  const double half = length / 2.0;
  double integral = 0.0;  // ∫ η(s) cos βs ds / depth
  switch (shape) {
    case DipShape::cosine: {
      // η = (h/2)(1 + cos 2πs/l): ∫cos βs = l·sinc(βl/2); the cosine term splits in two.
      const double gamma = 2.0 * kPi / length;
      integral = 0.5 * (length * sinc(beta * half) +
                        half * (sinc((gamma - beta) * half) + sinc((gamma + beta) * half)));
      break;
    }
    case DipShape::triangular:
      // η = h(1 − 2|s|/l): (l/2)·sinc²(βl/4).
      integral = half * std::pow(sinc(beta * length / 4.0), 2);
      break;
    case DipShape::parabolic:
      // η = h(1 − s²/A²), A = l/2: 4A (sin u − u cos u)/u³, u = βA.
      integral = 4.0 * half * parabola_kernel(beta * half);
      break;
  }
  return -2.0 * depth * integral / period;
}

}  // namespace railmodal
