#include "gear/harmonics.hpp"

#include <cmath>

namespace railmodal::gear {

std::vector<GearHarmonic> harmonics_of(const std::vector<double>& samples, int highest) {
  const int n = static_cast<int>(samples.size());
  std::vector<GearHarmonic> out(highest + 1);
  for (int k = 0; k <= highest; ++k) {
    double a = 0.0, b = 0.0;
    for (int i = 0; i < n; ++i) {
      const double angle = 2.0 * M_PI * k * i / n;
      a += samples[i] * std::cos(angle);
      b += samples[i] * std::sin(angle);
    }
    const double scale = (k == 0 ? 1.0 : 2.0) / n;
    out[k] = {k, a * scale, b * scale};
  }
  return out;
}

double synthesise(const std::vector<GearHarmonic>& harmonics, double angle) {
  double sum = 0.0;
  for (const GearHarmonic& h : harmonics) sum += h.cosine * std::cos(h.order * angle) + h.sine * std::sin(h.order * angle);
  return sum;
}

}  // namespace railmodal::gear
