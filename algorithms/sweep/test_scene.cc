#include "algorithms/sweep/test_scene.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>

namespace roofsweep {
namespace sweep_test {
namespace {

// Sum of sinusoids with wavelengths 0.25..2.5 m in the surface's metric
// coordinates: texture at every scale the sweep's 7 x 7 windows see.
struct Waves {
  static constexpr int kCount = 14;
  double kx[kCount], ky[kCount], phase[kCount], gain[kCount][3];
  explicit Waves(uint32_t seed) {
    std::mt19937 rng(seed * 7919u + 13u);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int i = 0; i < kCount; ++i) {
      const double angle = 2 * M_PI * U(rng);
      const double wavelength = 0.25 * std::pow(10.0, U(rng));
      kx[i] = 2 * M_PI * std::cos(angle) / wavelength;
      ky[i] = 2 * M_PI * std::sin(angle) / wavelength;
      phase[i] = 2 * M_PI * U(rng);
      const double g = 0.6 + 0.4 * U(rng);
      for (int ch = 0; ch < 3; ++ch) gain[i][ch] = g * (0.7 + 0.3 * std::cos(phase[i] + ch));
    }
  }
  Eigen::Vector3f At(double x, double y) const {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < kCount; ++i) {
      const double s = std::sin(kx[i] * x + ky[i] * y + phase[i]);
      for (int ch = 0; ch < 3; ++ch) sum[ch] += gain[i][ch] * s;
    }
    return (sum / kCount).cast<float>();
  }
};

}  // namespace

Block FourViewBlock() {
  Block block;
  block.source = "sweep-test";
  Camera cam;
  cam.id = "test";
  cam.width = 640;
  cam.height = 480;
  cam.fx = cam.fy = 1000;
  cam.cx = 320;
  cam.cy = 240;
  block.cameras.push_back(cam);
  const Eigen::Vector2d centres[4] = {{-12, -8}, {12, -8}, {-12, 8}, {12, 8}};
  for (int i = 0; i < 4; ++i) {
    View v;
    v.name = "v" + std::to_string(i);
    v.camera = 0;
    // Nadir: camera x east, y south (image north up), z down.
    v.pose.R = Eigen::Vector3d(1, -1, -1).asDiagonal();
    v.pose.C = Eigen::Vector3d(centres[i].x(), centres[i].y(), 100.0);
    block.views.push_back(v);
  }
  return block;
}

cv::Mat RenderView(const TestScene& scene, const Block& block, int view) {
  const View& v = block.views.at(view);
  const Camera& cam = block.CameraOf(v);
  cv::Mat image(cam.height, cam.width, CV_32FC3);
  std::vector<Eigen::Vector3d> normals;
  std::vector<Waves> waves;
  for (const Quad& q : scene.quads) {
    normals.push_back(q.u.cross(q.v).normalized());
    waves.emplace_back(q.seed);
  }
  const Waves ground(scene.ground_seed);
  std::mt19937 rng(1000u + static_cast<uint32_t>(view));
  std::normal_distribution<float> noise(0.0f, static_cast<float>(scene.noise_sigma));
  for (int r = 0; r < cam.height; ++r) {
    for (int c = 0; c < cam.width; ++c) {
      Eigen::Vector3f acc = Eigen::Vector3f::Zero();
      for (int sy = 0; sy < 2; ++sy) {
        for (int sx = 0; sx < 2; ++sx) {
          const Eigen::Vector2d px(c + 0.25 + 0.5 * sx, r + 0.25 + 0.5 * sy);
          const Ray ray = BackProject(cam, v.pose, px);
          double best = std::numeric_limits<double>::infinity();
          Eigen::Vector3f colour(0.3f, 0.3f, 0.3f);
          if (ray.direction.z() < 0) {
            best = (scene.ground_z - ray.origin.z()) / ray.direction.z();
            const Eigen::Vector3d X = ray.origin + best * ray.direction;
            colour = Eigen::Vector3f::Constant(0.35f) +
                     0.25f * (scene.ground_stripes_m > 0
                                  ? Eigen::Vector3f::Constant(static_cast<float>(
                                        std::sin(2 * M_PI * X.x() / scene.ground_stripes_m)))
                                  : ground.At(X.x(), X.y()));
          }
          for (size_t qi = 0; qi < scene.quads.size(); ++qi) {
            const Quad& q = scene.quads[qi];
            const Eigen::Vector3d& n = normals[qi];
            const double denom = n.dot(ray.direction);
            if (std::abs(denom) < 1e-12) continue;
            const double t = n.dot(q.origin - ray.origin) / denom;
            if (!(t > 0 && t < best)) continue;
            const Eigen::Vector3d X = ray.origin + t * ray.direction - q.origin;
            // Solve X = s u + t v in the least-squares sense (X is in the plane).
            Eigen::Matrix<double, 3, 2> M;
            M << q.u, q.v;
            const Eigen::Vector2d st = (M.transpose() * M).ldlt().solve(M.transpose() * X);
            if (st.x() < 0 || st.x() > 1 || st.y() < 0 || st.y() > 1) continue;
            best = t;
            const double xs = st.x() * q.u.norm(), ys = st.y() * q.v.norm();
            colour = q.colour;
            if (q.textured) colour += 0.3f * waves[qi].At(q.courses_along_u ? 0.1 * xs : xs, ys);
          }
          acc += colour;
        }
      }
      acc *= 0.25f;
      cv::Vec3f& out = image.at<cv::Vec3f>(r, c);
      for (int ch = 0; ch < 3; ++ch) out[ch] = std::clamp(acc[ch] + noise(rng), 0.0f, 1.0f);
    }
  }
  return image;
}

std::vector<cv::Mat> RenderAll(const TestScene& scene, const Block& block) {
  std::vector<cv::Mat> images;
  for (int v = 0; v < static_cast<int>(block.views.size()); ++v)
    images.push_back(RenderView(scene, block, v));
  return images;
}

}  // namespace sweep_test
}  // namespace roofsweep
