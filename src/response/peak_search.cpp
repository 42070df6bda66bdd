// Adaptive refinement of a damped resonance peak: golden-section search on a bracket.
#include <cmath>
#include <stdexcept>

#include "railmodal/response.hpp"

namespace railmodal {

Peak refine_peak(const LinearSystem& system, const ModalResult& modes, const ExcitationSource& source,
                 const OutputRequest& output, double low, double high, double relative_tolerance,
                 double friction_reference_amplitude) {
  if (!(low > 0.0) || !(high > low) || !(relative_tolerance > 0.0))
    throw std::invalid_argument("refine_peak: need 0 < low < high and a positive tolerance");
  Peak peak;
  auto amplitude = [&](double speed) {
    ++peak.evaluations;
    const auto curves = amplitude_curves(system, modes, source, 0, {output}, {speed}, friction_reference_amplitude);
    if (curves[0].unbounded[0]) peak.unbounded = true;
    return curves[0].amplitudes[0];
  };
  // Golden section keeps one interior point per step: the bracket shrinks by 0.618 per solve.
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = low, b = high;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = amplitude(c), fd = amplitude(d);
  while (b - a > relative_tolerance * 0.5 * (a + b) && !peak.unbounded) {
    if (fc >= fd) {
      b = d, d = c, fd = fc;
      c = b - ratio * (b - a);
      fc = amplitude(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + ratio * (b - a);
      fd = amplitude(d);
    }
  }
  peak.speed = fc >= fd ? c : d;
  peak.amplitude = std::max(fc, fd);
  return peak;
}

}  // namespace railmodal
