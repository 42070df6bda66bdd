// A reproducible stream of standard normal numbers: xoshiro256** (Blackman & Vigna, "Scrambled
// linear pseudorandom number generators", ACM TOMS 47(4), 2021) seeded through splitmix64
// (Steele, Lea & Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014), the
// seeding the generator's authors recommend, and the Box–Muller transform (Box & Muller, "A
// note on the generation of random normal deviates", Ann. Math. Stat. 29, 1958). Written out
// here rather than taken from <random>, whose distributions are implementation-defined: the
// same seed gives the same integers on every machine, and the same normals wherever the C
// library's log, cos and sin round alike (sqrt is exact by IEEE 754).
#pragma once

#include <cmath>
#include <cstdint>

namespace railmodal::ride {

class GaussianStream {
 public:
  explicit GaussianStream(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (std::uint64_t& word : state_) word = splitmix64(&x);
  }

  std::uint64_t next_integer() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

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

  /// splitmix64's step: also how independent streams are derived from one seed.
  static std::uint64_t splitmix64(std::uint64_t* x) {
    std::uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

}  // namespace railmodal::ride
