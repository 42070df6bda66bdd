// A portable pseudo-random sequence: xoshiro256** (Blackman & Vigna, "Scrambled linear
// pseudorandom number generators", ACM TOMS 47(4), 2021) seeded through splitmix64 (Steele, Lea
// & Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014), the seeding the
// generator's authors recommend. Written out rather than taken from <random>, whose
// distributions differ between standard libraries: the same seed gives the same integers and
// the same 53-bit uniforms on every machine (a study's seeded samples, a ride's track
// realisation). A foundation: any stage may include it.
#pragma once

#include <cstdint>

namespace railmodal {

/// splitmix64's step: spreads a small seed over a generator's state, and derives independent
/// streams from one seed.
inline std::uint64_t splitmix64(std::uint64_t* x) {
  std::uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Xoshiro256 {
 public:
  explicit Xoshiro256(std::uint64_t seed) {
    for (std::uint64_t& word : state_) word = splitmix64(&seed);
  }

  std::uint64_t next() {
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

  /// Uniform on [0, 1): the top 53 bits as a double's mantissa.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

}  // namespace railmodal
