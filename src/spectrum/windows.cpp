#include "spectrum/windows.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Every window here is a cosine sum w[n] = Σ_j (−1)^j a_j cos(2πjn/N).
const std::vector<double>& cosine_terms(Window window) {
  static const std::vector<double> rectangular{1.0};
  static const std::vector<double> hann{0.5, 0.5};
  // Matlab flattopwin and SciPy signal.windows.flattop.
  static const std::vector<double> flat_top{0.21557895, 0.41663158, 0.277263158, 0.083578947, 0.006947368};
  switch (window) {
    case Window::rectangular: return rectangular;
    case Window::hann: return hann;
    case Window::flat_top: return flat_top;
  }
  throw std::invalid_argument("unknown window");
}

double sinc(double x) { return x == 0.0 ? 1.0 : std::sin(kPi * x) / (kPi * x); }

}  // namespace

const char* to_string(Window window) {
  switch (window) {
    case Window::rectangular: return "rectangular";
    case Window::hann: return "hann";
    case Window::flat_top: return "flat-top";
  }
  return "?";
}

std::optional<Window> window_from_string(const std::string& word) {
  for (Window w : {Window::rectangular, Window::hann, Window::flat_top})
    if (word == to_string(w)) return w;
  return std::nullopt;
}

Eigen::VectorXd window_coefficients(Window window, Eigen::Index length) {
  if (length < 1) throw std::invalid_argument("window length must be at least 1, got " + std::to_string(length));
  const std::vector<double>& a = cosine_terms(window);
  Eigen::VectorXd w = Eigen::VectorXd::Constant(length, a[0]);
  for (size_t j = 1; j < a.size(); ++j) {
    const double sign = j % 2 ? -1.0 : 1.0;
    for (Eigen::Index n = 0; n < length; ++n) {
      // cos(2πjn/N) from the argument folded into [0, π]: w[n] and w[N − n] get the same bits.
      const Eigen::Index r = (static_cast<Eigen::Index>(j) * n) % length;
      const double folded = static_cast<double>(std::min(r, length - r));
      w(n) += sign * a[j] * std::cos(2.0 * kPi * folded / static_cast<double>(length));
    }
  }
  return w;
}

WindowProperties window_properties(Window window) {
  const std::vector<double>& a = cosine_terms(window);
  WindowProperties p;
  // Σw/N = a0 and N·Σw²/(Σw)² = (a0² + ½Σa_j²)/a0² exactly once N > 2·(terms − 1).
  p.coherent_gain = a[0];
  double power = a[0] * a[0];
  for (size_t j = 1; j < a.size(); ++j) power += 0.5 * a[j] * a[j];
  p.equivalent_noise_bandwidth = power / (a[0] * a[0]);
  // The response falls from 1 at ν = 0 to its first zero at ν = terms, crossing ½ once:
  // bisect for it.
  double lo = 0.0, hi = static_cast<double>(a.size());
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (spectrum::window_response(window, mid) > 0.5 ? lo : hi) = mid;
  }
  p.half_amplitude_bandwidth = lo + hi;  // twice the half-width
  p.worst_case_scalloping = spectrum::window_response(window, 0.5);
  return p;
}

namespace spectrum {

double window_response(Window window, double offset) {
  // The transform of the window centred on the record: a0·sinc(ν) + Σ ½a_j (sinc(ν−j) + sinc(ν+j));
  // centring turns the alternating signs of the cosine sum into plus signs.
  const std::vector<double>& a = cosine_terms(window);
  double w = a[0] * sinc(offset);
  for (size_t j = 1; j < a.size(); ++j) {
    const double shift = static_cast<double>(j);
    w += 0.5 * a[j] * (sinc(offset - shift) + sinc(offset + shift));
  }
  return std::abs(w) / a[0];
}

}  // namespace spectrum
}  // namespace railmodal
