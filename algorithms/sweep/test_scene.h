#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/geometry/block.h"

namespace roofsweep {
namespace sweep_test {

// A tiny ray caster for the sweep's tests: planar parallelograms over a
// textured ground plane. rs_simulate's renderer needs a whole procedural
// town; these tests need one line with chosen planes attached.
struct Quad {
  Eigen::Vector3d origin, u, v;  // points origin + s u + t v, s, t in [0, 1]
  bool textured = true;
  // Texture stretched tenfold along u (wavelengths of 2.5-25 m): tile
  // courses parallel to u.
  bool courses_along_u = false;
  Eigen::Vector3f colour = Eigen::Vector3f(0.5f, 0.4f, 0.35f);
  uint32_t seed = 1;
};

struct TestScene {
  std::vector<Quad> quads;
  double ground_z = 0;
  uint32_t ground_seed = 99;
  // > 0: the ground is stripes across x of this wavelength (m; mowing
  // stripes, parking bays), a texture that repeats along the x baselines.
  double ground_stripes_m = 0;
  double noise_sigma = 0.004;  // per channel, [0, 1] units
};

// Four nadir 640 x 480 views (f = 1000 px) 100 m above the ground around
// the origin, with baselines of 24 and 16 m.
Block FourViewBlock();

// CV_32FC3 RGB [0, 1], 2 x 2 samples per pixel, deterministic noise.
cv::Mat RenderView(const TestScene& scene, const Block& block, int view);
std::vector<cv::Mat> RenderAll(const TestScene& scene, const Block& block);

}  // namespace sweep_test
}  // namespace roofsweep
