#include "algorithms/simulate/camera_layout.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "algorithms/core/error.h"
#include "algorithms/simulate/random.h"

namespace roofsweep {
namespace sim {

Camera LayoutCamera(const CameraLayoutOptions& o) {
  Camera c;
  c.id = "sim_frame";
  c.width = o.image_width;
  c.height = o.image_height;
  c.fx = c.fy = o.focal_mm * 1000.0 / o.pixel_size_um;
  c.cx = o.image_width / 2.0;
  c.cy = o.image_height / 2.0;
  c.k1 = o.k1, c.k2 = o.k2, c.k3 = o.k3, c.p1 = o.p1, c.p2 = o.p2;
  c.pixel_size_mm = o.pixel_size_um / 1000.0;
  return c;
}

double FlyingHeight(const CameraLayoutOptions& o) {
  return o.gsd * o.focal_mm * 1000.0 / o.pixel_size_um;
}

namespace {

// World-to-camera rotation (CV axes) from the optical axis and the world
// direction the image's +y (down) axis should follow.
Eigen::Matrix3d LookRotation(const Eigen::Vector3d& forward, const Eigen::Vector3d& down_hint) {
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d y = (down_hint - down_hint.dot(z) * z).normalized();
  const Eigen::Vector3d x = y.cross(z);
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = y.transpose();
  R.row(2) = z.transpose();
  return R;
}

}  // namespace

std::vector<SimulatedView> LayoutCameras(const Eigen::Vector4d& area, double ground_z,
                                         const CameraLayoutOptions& o, uint64_t seed) {
  if (o.image_width < 16 || o.image_height < 16)
    throw Error("simulate: image size must be >= 16 px");
  if (!(o.gsd > 0) || !(o.focal_mm > 0) || !(o.pixel_size_um > 0))
    throw Error("simulate: gsd, focal_mm and pixel_size_um must be positive");
  if (!(o.forward_overlap >= 0 && o.forward_overlap < 0.95) ||
      !(o.side_overlap >= 0 && o.side_overlap < 0.95))
    throw Error("simulate: overlaps must be in [0, 0.95)");
  const Camera cam = LayoutCamera(o);
  const double H = FlyingHeight(o);
  const double h = o.heading_deg * M_PI / 180;
  const Eigen::Vector3d along(std::cos(h), std::sin(h), 0);
  const Eigen::Vector3d across(std::sin(h), -std::cos(h), 0);  // to the right of the flight
  // With the image's top towards the flight direction, image columns run
  // across the track and rows along it.
  const double foot_along = o.image_height * o.gsd, foot_across = o.image_width * o.gsd;
  const double base = (1 - o.forward_overlap) * foot_along;
  const double spacing = (1 - o.side_overlap) * foot_across;
  // Extent of the area in the flight frame.
  const Eigen::Vector2d centre(0.5 * (area[0] + area[2]), 0.5 * (area[1] + area[3]));
  double a0 = 1e300, a1 = -1e300, c0 = 1e300, c1 = -1e300;
  for (double x : {area[0], area[2]})
    for (double y : {area[1], area[3]}) {
      const Eigen::Vector3d d(x - centre.x(), y - centre.y(), 0);
      a0 = std::min(a0, d.dot(along)), a1 = std::max(a1, d.dot(along));
      c0 = std::min(c0, d.dot(across)), c1 = std::max(c1, d.dot(across));
    }
  const int n_strips =
      o.strips > 0
          ? o.strips
          : std::max(
                1, static_cast<int>(std::ceil(std::max(0.0, c1 - c0 - foot_across) / spacing)) + 1);
  const int n_images = o.images_per_strip > 0 ? o.images_per_strip
                                              : static_cast<int>(std::ceil((a1 - a0) / base)) + 1;
  Rng rng(Hash(seed, 0xca3e7a));
  std::vector<SimulatedView> views;
  for (int s = 0; s < n_strips; ++s) {
    const double off_across = (s - 0.5 * (n_strips - 1)) * spacing;
    const bool back = o.serpentine && (s % 2 == 1);
    const Eigen::Vector3d dir = back ? Eigen::Vector3d(-along) : along;
    for (int k = 0; k < n_images; ++k) {
      const int i = back ? n_images - 1 - k : k;  // stations in flight order
      const double off_along = (i - 0.5 * (n_images - 1)) * base;
      Eigen::Vector3d C(centre.x(), centre.y(), ground_z + H);
      C += off_along * along + off_across * across;
      const Eigen::Vector3d noise_pos(rng.Normal(), rng.Normal(), rng.Normal());
      C += o.position_sigma_m * noise_pos;
      // Nadir: optical axis down, image top (-y) towards the flight direction.
      Eigen::Matrix3d R = LookRotation(Eigen::Vector3d(0, 0, -1), -dir);
      const Eigen::Vector3d att(rng.Normal(), rng.Normal(), rng.Normal());
      if (o.attitude_sigma_deg > 0) {
        const Eigen::Vector3d aa = att * o.attitude_sigma_deg * M_PI / 180;
        R = Eigen::AngleAxisd(aa.norm(), aa.norm() > 0 ? Eigen::Vector3d(aa.normalized())
                                                       : Eigen::Vector3d::UnitZ())
                .toRotationMatrix() *
            R;
      }
      char name[32];
      std::snprintf(name, sizeof name, "s%02d_i%03d", s + 1, k + 1);
      SimulatedView v{name, cam, Pose{R, C}, s, k, "nadir"};
      views.push_back(v);
      if (o.obliques) {
        const double t = o.oblique_tilt_deg * M_PI / 180;
        const Eigen::Vector3d down(0, 0, -1);
        const Eigen::Vector3d right = dir.cross(Eigen::Vector3d::UnitZ());
        struct Look {
          const char* name;
          Eigen::Vector3d horizontal;
        };
        for (const Look& l : {Look{"forward", dir}, Look{"backward", -dir}, Look{"left", -right},
                              Look{"right", right}}) {
          const Eigen::Vector3d fwd = std::cos(t) * down + std::sin(t) * l.horizontal;
          // Image top points away from the camera on the ground (horizon up).
          SimulatedView ov{std::string(name) + "_" + l.name,
                           cam,
                           Pose{LookRotation(fwd, -l.horizontal), C},
                           s,
                           k,
                           l.name};
          views.push_back(ov);
        }
      }
    }
  }
  return views;
}

}  // namespace sim
}  // namespace roofsweep
