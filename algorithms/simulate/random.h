#pragma once

#include <cmath>
#include <cstdint>

namespace roofsweep {
namespace sim {

// Counter-based randomness: every random number the simulator uses is a hash
// of (seed, purpose, indices), never the state of a shared generator, so the
// output does not depend on the order or thread in which pixels and objects
// are processed.

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mixer.
inline uint64_t Mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

inline uint64_t Hash(uint64_t a) { return Mix64(a); }
inline uint64_t Hash(uint64_t a, uint64_t b) { return Mix64(Mix64(a) ^ b); }
inline uint64_t Hash(uint64_t a, uint64_t b, uint64_t c) { return Mix64(Hash(a, b) ^ c); }
inline uint64_t Hash(uint64_t a, uint64_t b, uint64_t c, uint64_t d) {
  return Mix64(Hash(a, b, c) ^ d);
}

// Uniform in [0, 1) from the top 53 bits.
inline double ToUnit(uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

// A small sequential generator for one object (a building, a pixel), seeded
// from a hash; owned by one thread at a time.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t Next() { return Mix64(state_++ * 0x2545f4914f6cdd1dULL); }
  double Uniform() { return ToUnit(Next()); }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  int Int(int lo, int hi_inclusive) {
    return lo + static_cast<int>(Uniform() * (hi_inclusive - lo + 1));
  }
  bool Chance(double p) { return Uniform() < p; }
  // Standard normal by Box–Muller (one value per call; simple, deterministic).
  double Normal() {
    const double u1 = 1.0 - Uniform();
    const double u2 = Uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  uint64_t state_;
};

}  // namespace sim
}  // namespace roofsweep
