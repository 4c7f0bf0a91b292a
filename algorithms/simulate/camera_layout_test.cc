#include "algorithms/simulate/camera_layout.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "algorithms/core/error.h"

namespace roofsweep {
namespace sim {
namespace {

Eigen::Vector3d Ground(const SimulatedView& v, double x, double y, double z) {
  return *IntersectHorizontalPlane(BackProject(v.camera, v.pose, Eigen::Vector2d(x, y)), z);
}

// Overlap measured from the images: the share of image i's extent along
// `axis` (ground direction) that image j also covers, from the projections
// of image corners onto the ground.
double MeasuredOverlap(const SimulatedView& a, const SimulatedView& b, const Eigen::Vector3d& axis,
                       double z) {
  auto extent = [&](const SimulatedView& v) {
    double lo = 1e300, hi = -1e300;
    for (double x : {0.0, double(v.camera.width)})
      for (double y : {0.0, double(v.camera.height)}) {
        const double s = Ground(v, x, y, z).dot(axis);
        lo = std::min(lo, s), hi = std::max(hi, s);
      }
    return std::make_pair(lo, hi);
  };
  const auto ea = extent(a), eb = extent(b);
  return std::max(0.0, std::min(ea.second, eb.second) - std::max(ea.first, eb.first)) /
         (ea.second - ea.first);
}

TEST(CameraLayout, RequestedOverlapsAndGsd) {
  for (double heading : {0.0, 37.0}) {
    CameraLayoutOptions o;
    o.image_width = 3000;
    o.image_height = 2000;
    o.gsd = 0.08;
    o.forward_overlap = 0.75;
    o.side_overlap = 0.3;
    o.heading_deg = heading;
    const double z = 120;
    const auto views = LayoutCameras(Eigen::Vector4d(-300, -200, 300, 200), z, o, 7);
    ASSERT_GE(views.size(), 6u);
    const double h = heading * M_PI / 180;
    const Eigen::Vector3d along(std::cos(h), std::sin(h), 0), across(std::sin(h), -std::cos(h), 0);
    int strips = 0, pairs = 0;
    for (size_t i = 0; i + 1 < views.size(); ++i) {
      strips = std::max(strips, views[i].strip + 1);
      if (views[i].strip == views[i + 1].strip) {
        EXPECT_NEAR(MeasuredOverlap(views[i], views[i + 1], along, z), 0.75, 1e-6);
        ++pairs;
      }
    }
    EXPECT_GE(strips, 2);
    EXPECT_GT(pairs, 4);
    // Side overlap between the first images of strip 0 and strip 1.
    const SimulatedView* s1 = nullptr;
    for (const auto& v : views)
      if (v.strip == 1 && !s1) s1 = &v;
    ASSERT_NE(s1, nullptr);
    EXPECT_NEAR(MeasuredOverlap(views[0], *s1, across, z), 0.3, 1e-6);
    // GSD at the image centre and flying height.
    const SimulatedView& v = views[0];
    const double gsd = (Ground(v, 1500, 1000, z) - Ground(v, 1501, 1000, z)).norm();
    EXPECT_NEAR(gsd, 0.08, 1e-9);
    EXPECT_NEAR(v.pose.C.z() - z, FlyingHeight(o), 1e-9);
    // Image top points along the flight direction.
    const Eigen::Vector3d up_dir = Ground(v, 1500, 0, z) - Ground(v, 1500, 2000, z);
    const Eigen::Vector3d fly = v.strip % 2 == 0 ? along : Eigen::Vector3d(-along);
    EXPECT_GT(up_dir.normalized().dot(fly), 0.999);
    // Every area corner is covered by at least one image.
    for (double x : {-300.0, 300.0})
      for (double y : {-200.0, 200.0}) {
        bool seen = false;
        for (const auto& w : views) {
          auto p = Project(w.camera, w.pose, Eigen::Vector3d(x, y, z));
          seen = seen || (p && p->x() >= 0 && p->y() >= 0 && p->x() <= w.camera.width &&
                          p->y() <= w.camera.height);
        }
        EXPECT_TRUE(seen) << x << " " << y;
      }
  }
}

TEST(CameraLayout, ObliquesLookOutwardAtTheTilt) {
  CameraLayoutOptions o;
  o.strips = 1;
  o.images_per_strip = 1;
  o.obliques = true;
  o.oblique_tilt_deg = 40;
  const auto views = LayoutCameras(Eigen::Vector4d(-10, -10, 10, 10), 0, o, 1);
  ASSERT_EQ(views.size(), 5u);
  for (size_t i = 1; i < 5; ++i) {
    const double angle = std::acos(-views[i].pose.ViewingDirection().z()) * 180 / M_PI;
    EXPECT_NEAR(angle, 40, 1e-9) << views[i].look;
    EXPECT_NEAR(views[i].pose.R.determinant(), 1, 1e-12);
    // The horizon side of the image is at the top: the bottom row sees nearer ground.
    const auto top = Ground(views[i], 1024, 100, 0), bottom = Ground(views[i], 1024, 1948, 0);
    EXPECT_GT((top - views[i].pose.C).norm(), (bottom - views[i].pose.C).norm());
  }
}

TEST(CameraLayout, RejectsBadOptions) {
  CameraLayoutOptions o;
  o.forward_overlap = 1.2;
  EXPECT_THROW(LayoutCameras(Eigen::Vector4d(0, 0, 1, 1), 0, o, 1), Error);
}

}  // namespace
}  // namespace sim
}  // namespace roofsweep
