// A reproducible stream of standard normal numbers: the portable xoshiro256** integers
// (xoshiro256.hpp) and the Box–Muller transform (Box & Muller, "A note on the generation of
// random normal deviates", Ann. Math. Stat. 29, 1958), the same normals wherever the C
// library's log, cos and sin round alike (sqrt is exact by IEEE 754).
#pragma once

#include <cmath>
#include <cstdint>

#include "xoshiro256.hpp"

namespace railmodal::ride {

class GaussianStream {
 public:
  explicit GaussianStream(std::uint64_t seed) : generator_(seed) {}

  std::uint64_t next_integer() { return generator_.next(); }

  /// Uniform on (0, 1]: the top 53 bits, shifted by one ulp so that log never sees 0.
  double next_uniform() { return (static_cast<double>(next_integer() >> 11) + 1.0) * 0x1.0p-53; }

  /// Two independent standard normals (Box–Muller): √(−2 ln u₁)·(cos 2πu₂, sin 2πu₂).
  void next_normal_pair(double* first, double* second) {
    constexpr double kTwoPi = 6.28318530717958647692;
    const double radius = std::sqrt(-2.0 * std::log(next_uniform()));
    const double angle = kTwoPi * next_uniform();
    *first = radius * std::cos(angle);
    *second = radius * std::sin(angle);
  }

  /// Moves past one pair of next_normal_pair without forming it (its two uniforms drawn, no
  /// log, sine or cosine): the stream then stands where next_normal_pair would leave it.
  void skip_normal_pair() {
    next_integer();
    next_integer();
  }

 private:
  Xoshiro256 generator_;
};

}  // namespace railmodal::ride
