#include "algorithms/simulate/noise.h"

#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace sim {
namespace {

inline uint32_t Hash32(int32_t i, int32_t j, uint32_t seed) {
  uint32_t h = static_cast<uint32_t>(i) * 0x8da6b343u ^ static_cast<uint32_t>(j) * 0xd8163841u ^
               seed * 0xcb1ab31fu;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  return h;
}

inline float Fade(float t) { return t * t * t * (t * (t * 6.f - 15.f) + 10.f); }

inline float Grad(int32_t i, int32_t j, uint32_t seed, float dx, float dy) {
  // 8 gradient directions: cheap and isotropic enough for textures.
  static const float kG[8][2] = {{1, 0},
                                 {-1, 0},
                                 {0, 1},
                                 {0, -1},
                                 {0.7071f, 0.7071f},
                                 {-0.7071f, 0.7071f},
                                 {0.7071f, -0.7071f},
                                 {-0.7071f, -0.7071f}};
  const float* g = kG[(Hash32(i, j, seed) >> 13) & 7u];
  return g[0] * dx + g[1] * dy;
}

}  // namespace

float CellRandom(int32_t i, int32_t j, uint32_t seed) {
  return static_cast<float>(Hash32(i, j, seed ^ 0x5bd1e995u) >> 8) * (1.0f / 16777216.0f);
}

inline int32_t FastFloor(float x) {
  const int32_t i = static_cast<int32_t>(x);
  return i - (x < static_cast<float>(i));
}

float GradientNoise(float x, float y, uint32_t seed) {
  const int32_t i = FastFloor(x), j = FastFloor(y);
  const float fx = static_cast<float>(i), fy = static_cast<float>(j);
  const float dx = x - fx, dy = y - fy;
  const float u = Fade(dx), v = Fade(dy);
  const float n00 = Grad(i, j, seed, dx, dy);
  const float n10 = Grad(i + 1, j, seed, dx - 1, dy);
  const float n01 = Grad(i, j + 1, seed, dx, dy - 1);
  const float n11 = Grad(i + 1, j + 1, seed, dx - 1, dy - 1);
  const float a = n00 + u * (n10 - n00);
  const float b = n01 + u * (n11 - n01);
  return 1.4142f * (a + v * (b - a));
}

float FractalNoise(float x, float y, float base_frequency, int octaves, float gain, float footprint,
                   uint32_t seed) {
  float sum = 0, amp = 1, norm = 0, f = base_frequency;
  for (int o = 0; o < octaves; ++o) {
    // Nyquist: a feature of size 1/f needs about 2 samples; fade between
    // f*footprint = 0.25 and 0.5 instead of cutting abruptly.
    const float w = std::clamp(2.0f - 4.0f * f * footprint, 0.0f, 1.0f);
    if (w <= 0) break;
    sum += w * amp * GradientNoise(x * f + 17.3f * o, y * f - 9.1f * o, seed + 101u * o);
    norm += amp;
    amp *= gain;
    f *= 2;
  }
  return norm > 0 ? sum / norm : 0.0f;
}

}  // namespace sim
}  // namespace roofsweep
