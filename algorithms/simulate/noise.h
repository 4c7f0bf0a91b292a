#pragma once

#include <cstdint>

namespace roofsweep {
namespace sim {

// Band-limited procedural noise for textures. Written here because neither
// OpenCV nor Eigen offers gradient noise, and the texture must be evaluated
// at arbitrary surface points (not on a raster) without state.

// Gradient (Perlin-style) noise in 2D, value in about [-1, 1], feature size 1.
float GradientNoise(float x, float y, uint32_t seed);

// Fractal sum of GradientNoise octaves starting at `base_frequency` (1/m),
// each octave doubling the frequency and scaling the amplitude by `gain`.
// Octaves finer than the sampling footprint `footprint` (m) are faded out,
// so textures do not alias when seen from far away. Result about [-1, 1].
float FractalNoise(float x, float y, float base_frequency, int octaves, float gain, float footprint,
                   uint32_t seed);

// Hash of an integer cell to [0, 1).
float CellRandom(int32_t i, int32_t j, uint32_t seed);

}  // namespace sim
}  // namespace roofsweep
