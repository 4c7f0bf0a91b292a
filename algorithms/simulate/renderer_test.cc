#include "algorithms/simulate/renderer.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "algorithms/simulate/presets.h"

namespace roofsweep {
namespace sim {
namespace {

using V3 = Eigen::Vector3d;

Camera TestCamera(int size, double f) {
  Camera c;
  c.width = c.height = size;
  c.fx = c.fy = f;
  c.cx = c.cy = size / 2.0;
  return c;
}

Eigen::Matrix3d LookDown(double yaw_deg, double tilt_x_deg, double tilt_y_deg) {
  // Nadir (camera z = world -z), then rotated about the camera's own axes.
  Eigen::Matrix3d R0;
  R0 << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(tilt_x_deg * M_PI / 180, V3::UnitX()) *
                                Eigen::AngleAxisd(tilt_y_deg * M_PI / 180, V3::UnitY()))
                                   .toRotationMatrix();
  return tilt * R0 * Eigen::AngleAxisd(yaw_deg * M_PI / 180, V3::UnitZ()).toRotationMatrix();
}

cv::Mat Grey(const cv::Mat& rgb) {
  cv::Mat g;
  if (rgb.depth() == CV_8U) {
    rgb.convertTo(g, CV_32FC3);
  } else {
    g = rgb;
  }
  cv::Mat out;
  cv::transform(g, out, cv::Matx13f(0.2126f, 0.7152f, 0.0722f));
  return out;
}

// A flat textured ground (paving, lawn, asphalt, paint) and nothing else.
Scene PlaneScene() {
  SceneOptions o;
  o.building_count = 0;
  o.tree_count = 0;
  o.extent_x = o.extent_y = 200;
  o.street_spacing = 35;
  return GenerateScene(o, 5);
}

// Least-squares translation (Lucas–Kanade, Gauss–Newton) that maps patch r
// of b onto a: b(x + s) ~ a(x). OpenCV's ECC lives in the video module,
// which roofsweep does not link.
cv::Point2d AlignTranslation(const cv::Mat& a, const cv::Mat& b, const cv::Rect& r) {
  cv::Mat gx, gy;
  cv::Sobel(b, gx, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(b, gy, CV_32F, 0, 1, 3, 1.0 / 8);
  cv::Point2d s(0, 0);
  for (int it = 0; it < 30; ++it) {
    cv::Mat mx(r.size(), CV_32F), my(r.size(), CV_32F);
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        mx.at<float>(y, x) = static_cast<float>(r.x + x + s.x);
        my.at<float>(y, x) = static_cast<float>(r.y + y + s.y);
      }
    cv::Mat bw, gxw, gyw;
    cv::remap(b, bw, mx, my, cv::INTER_CUBIC);
    cv::remap(gx, gxw, mx, my, cv::INTER_CUBIC);
    cv::remap(gy, gyw, mx, my, cv::INTER_CUBIC);
    const cv::Mat e = a(r) - bw;
    const double axx = gxw.dot(gxw), axy = gxw.dot(gyw), ayy = gyw.dot(gyw);
    const double bx = gxw.dot(e), by = gyw.dot(e);
    const double det = axx * ayy - axy * axy;
    if (det <= 0) break;
    const cv::Point2d step((ayy * bx - axy * by) / det, (axx * by - axy * bx) / det);
    s += step;
    if (std::hypot(step.x, step.y) < 1e-5) break;
  }
  return s;
}

// Sub-pixel shift between two images over a grid of patches; returns the
// largest patch shift (px).
// Returns the largest patch shift (px), *median the median.
double MaxPatchShift(const cv::Mat& a, const cv::Mat& b, const cv::Mat& valid, int* patches,
                     double* median = nullptr) {
  const int P = 96;
  double worst = 0;
  std::vector<double> all;
  *patches = 0;
  for (int y = 0; y + P <= a.rows; y += P / 2)
    for (int x = 0; x + P <= a.cols; x += P / 2) {
      const cv::Rect r(x, y, P, P);
      if (cv::countNonZero(valid(r)) < P * P) continue;
      cv::Scalar mean, sd;
      cv::meanStdDev(a(r), mean, sd);
      if (sd[0] < 0.02 * mean[0]) continue;  // featureless
      const cv::Point2d t = AlignTranslation(a, b, r);
      const double s = std::hypot(t.x, t.y);
      worst = std::max(worst, s);
      all.push_back(s);
      ++*patches;
    }
  if (median && !all.empty()) {
    std::sort(all.begin(), all.end());
    *median = all[all.size() / 2];
  }
  return worst;
}

// Renders a textured plane in two views and checks that view 2, warped by
// the analytic plane-induced homography H = K2 (R - t nᵀ/d) K1⁻¹ (with view
// 2's lens distortion applied on top), lands on view 1 to sub-pixel
// accuracy. A control warp shifted by 0.4 px must be caught.
TEST(Renderer, PlaneInducedHomographyBetweenViews) {
  const Scene scene = PlaneScene();
  RenderOptions ro;
  ro.supersampling = 4;
  ro.shadows = false;
  const Renderer renderer(scene, ro);
  const int N = 512;
  Camera c1 = TestCamera(N, 1200), c2 = TestCamera(N, 1350);
  c2.k1 = -0.06;
  c2.k2 = 0.02;
  c2.p1 = 0.001;
  const Pose p1{LookDown(0, 0, 0), V3(3, -2, 150)};
  const Pose p2{LookDown(20, 8, -6), V3(22, 10, 160)};
  const double z0 = scene.ground.z;
  cv::Mat i1 = Grey(renderer.RenderRadiance(c1, p1, 0, 1));
  cv::Mat i2 = Grey(renderer.RenderRadiance(c2, p2, 1, 1));
  // Same optical blur in both, as a camera would have.
  cv::GaussianBlur(i1, i1, cv::Size(0, 0), 1.0);
  cv::GaussianBlur(i2, i2, cv::Size(0, 0), 1.0);

  // Plane in camera-1 coordinates: n1ᵀ X1 + d = 0.
  const V3 n1 = p1.R * V3::UnitZ();
  const double d = -n1.dot(p1.R * (V3(0, 0, z0) - p1.C));
  const Eigen::Matrix3d R = p2.R * p1.R.transpose();
  const V3 t = p2.R * (p1.C - p2.C);
  const Eigen::Matrix3d Hn = R - t * n1.transpose() / d;  // normalised -> normalised
  auto build_map = [&](double shift_x, cv::Mat* mx, cv::Mat* my, cv::Mat* valid) {
    mx->create(N, N, CV_32F);
    my->create(N, N, CV_32F);
    *valid = cv::Mat::zeros(N, N, CV_8U);
    for (int y = 0; y < N; ++y)
      for (int x = 0; x < N; ++x) {
        const V3 q1((x + 0.5 - c1.cx) / c1.fx, (y + 0.5 - c1.cy) / c1.fy, 1);
        const V3 q2 = Hn * q1;
        const Eigen::Vector2d px = c2.NormalizedToPixel(q2.head<2>() / q2.z());
        mx->at<float>(y, x) = static_cast<float>(px.x() - 0.5 + shift_x);  // corner -> index
        my->at<float>(y, x) = static_cast<float>(px.y() - 0.5);
        valid->at<uchar>(y, x) = px.x() > 3 && px.y() > 3 && px.x() < N - 3 && px.y() < N - 3;
      }
  };
  cv::Mat mx, my, valid, warped;
  build_map(0.0, &mx, &my, &valid);
  cv::remap(i2, warped, mx, my, cv::INTER_CUBIC, cv::BORDER_CONSTANT, 0);
  int patches = 0;
  double median = 1e9;
  const double worst = MaxPatchShift(i1, warped, valid, &patches, &median);
  EXPECT_GE(patches, 12);
  // Residuals are texture aliasing that differs between the views, not
  // geometry: a wrong pose or pixel convention shifts every patch alike.
  EXPECT_LT(median, 0.03) << "median patch misalignment, px";
  EXPECT_LT(worst, 0.12) << "largest patch misalignment, px";
  // Photometric agreement: the same surface with the same normal and sun.
  cv::Mat diff;
  cv::absdiff(i1, warped, diff);
  const double mad = cv::mean(diff, valid)[0] / cv::mean(i1, valid)[0];
  EXPECT_LT(mad, 0.03);
  // Control: a warp off by 0.4 px is detected as such.
  build_map(0.4, &mx, &my, &valid);
  cv::remap(i2, warped, mx, my, cv::INTER_CUBIC, cv::BORDER_CONSTANT, 0);
  const double control = MaxPatchShift(i1, warped, valid, &patches);
  EXPECT_GT(control, 0.3);  // 0.4 px in view 2 is ~0.35 px in view 1
  RecordProperty("max_patch_shift_px", std::to_string(worst));
  std::printf(
      "homography: %d patches, median shift %.4f px, max %.4f px, MAD %.4f, control %.3f px\n",
      patches, median, worst, mad, control);
}

// Projected ground-truth roof edges land on intensity edges: along each
// visible edge with contrast, the gradient maximum across the edge lies
// within a fraction of a pixel of the projected line.
TEST(Renderer, TrueRoofEdgesLandOnImageEdges) {
  SimulationOptions o = SimulationPreset("easy");
  o.scene.extent_x = o.scene.extent_y = 90;
  o.scene.building_count = 10;
  // Paths, beds and cars beside walls put other gradient peaks into the
  // profile window; this test is about projection geometry.
  o.scene.clutter = false;
  const Scene scene = GenerateScene(o.scene, 3);
  const SceneTruth truth = TruthOf(scene);
  const Renderer renderer(scene, o.render);
  std::vector<std::pair<Camera, Pose>> views;
  const Camera cam = TestCamera(1024, 1100);
  views.push_back({cam, Pose{LookDown(10, 0, 0), V3(0, 0, 110)}});
  Camera dist = cam;
  dist.k1 = -0.05;
  views.push_back({dist, Pose{LookDown(-30, 20, 5), V3(20, -45, 100)}});
  std::vector<double> offsets;
  for (size_t vi = 0; vi < views.size(); ++vi) {
    const auto& [c, p] = views[vi];
    SimulatedView sv{"t", c, p, 0, 0, "nadir"};
    const cv::Mat img = Grey(renderer.Render(sv, static_cast<int>(vi), 9));
    const GeometryMaps geo = renderer.RenderGeometry(c, p);
    auto bilinear = [&](const cv::Mat& m, double x, double y) {  // corner-origin coords
      cv::Mat patch;
      cv::getRectSubPix(m, cv::Size(1, 1), cv::Point2f(float(x - 0.5), float(y - 0.5)), patch,
                        CV_32F);
      return patch.at<float>(0, 0);
    };
    for (const TrueEdge& e : truth.edges) {
      if (!IsRoofEdge(e.kind)) continue;
      const double len = (e.b - e.a).norm();
      for (double s = 0.15; s <= 0.85; s += 0.7 / std::max(1.0, len / 0.5)) {
        const V3 X = e.a + s * (e.b - e.a);
        const auto q = Project(c, p, X);
        const auto q2 = Project(c, p, X + 0.01 * (e.b - e.a).normalized());
        if (!q || !q2) continue;
        const Eigen::Vector2d dir = (*q2 - *q).normalized();
        const Eigen::Vector2d nrm(-dir.y(), dir.x());
        if (q->minCoeff() < 8 || q->x() > c.width - 8 || q->y() > c.height - 8) continue;
        // Visible: the surface seen at the edge point is the edge itself.
        const int ix = static_cast<int>(q->x()), iy = static_cast<int>(q->y());
        const double depth = (p.R * (X - p.C)).z();
        bool visible = false;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            visible = visible || std::abs(geo.depth.at<float>(iy + dy, ix + dx) - depth) <
                                     0.02 * depth / 100 + 0.05;
        if (!visible) continue;
        // Both sides are single, different faces (no other edge nearby).
        auto face_at = [&](double off) {
          const Eigen::Vector2d r = *q + off * nrm;
          return geo.face.at<int>(static_cast<int>(r.y()), static_cast<int>(r.x()));
        };
        if (face_at(-1.5) != face_at(-4) || face_at(1.5) != face_at(4) ||
            face_at(-1.5) == face_at(1.5))
          continue;
        // Intensity profile across the edge.
        std::vector<double> prof;
        for (double t = -4; t <= 4.001; t += 0.25) {
          const Eigen::Vector2d r = *q + t * nrm;
          prof.push_back(bilinear(img, r.x(), r.y()));
        }
        if (std::abs(prof.back() - prof.front()) < 12) continue;  // no contrast
        int best = 1;
        for (int k = 1; k + 1 < static_cast<int>(prof.size()); ++k)
          if (std::abs(prof[k + 1] - prof[k - 1]) > std::abs(prof[best + 1] - prof[best - 1]))
            best = k;
        if (best < 2 || best > static_cast<int>(prof.size()) - 3) {
          offsets.push_back(4.0);  // gradient peak at the window border: a miss
          continue;
        }
        auto g = [&](int k) { return std::abs(prof[k + 1] - prof[k - 1]); };
        const double a = g(best - 1), b = g(best), cc = g(best + 1);
        const double sub = (a - 2 * b + cc) != 0 ? 0.5 * (a - cc) / (a - 2 * b + cc) : 0;
        offsets.push_back(std::abs(-4 + 0.25 * (best + sub)));
      }
    }
  }
  ASSERT_GT(offsets.size(), 300u);
  std::sort(offsets.begin(), offsets.end());
  const double median = offsets[offsets.size() / 2];
  const double p90 = offsets[offsets.size() * 9 / 10];
  std::printf("edge profiles: %zu, median |offset| %.3f px, 90%% %.3f px\n", offsets.size(), median,
              p90);
  EXPECT_LT(median, 0.2);
  EXPECT_LT(p90, 0.5);
}

TEST(Renderer, DeterministicForSeedAndThreadCount) {
  SimulationOptions o = SimulationPreset("realistic");
  o.scene.extent_x = o.scene.extent_y = 80;
  o.scene.building_count = 8;
  o.scene.tree_count = 6;
  const Scene scene = GenerateScene(o.scene, 11);
  const Renderer renderer(scene, o.render);
  SimulatedView v{"t", TestCamera(256, 500), Pose{LookDown(5, 3, 0), V3(1, 2, 60)}, 1, 0, "nadir"};
  const cv::Mat a = renderer.Render(v, 3, 42);
  const cv::Mat b = renderer.Render(v, 3, 42);
  cv::Mat c;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    c = renderer.Render(v, 3, 42);
  }
  const cv::Mat d = renderer.Render(v, 3, 43);
  ASSERT_EQ(a.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a, c, cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(a, d, cv::NORM_L1), 0);  // another seed, other noise
  // The scene itself is a function of the seed.
  const Scene again = GenerateScene(o.scene, 11);
  ASSERT_EQ(again.city.buildings.size(), scene.city.buildings.size());
  for (size_t i = 0; i < scene.city.buildings.size(); ++i)
    EXPECT_EQ(again.city.buildings[i].surfaces[0].polygons[0].exterior[0],
              scene.city.buildings[i].surfaces[0].polygons[0].exterior[0]);
}

TEST(Renderer, DepthAndFaceMapsMatchTheScene) {
  SceneOptions so;
  so.extent_x = so.extent_y = 80;
  so.building_count = 8;
  so.tree_count = 0;
  // Chimneys and solar panels may sit on a face's centroid; they are
  // checked in RoofObjectsAreOccludersNotRoofPlanes.
  so.roof_objects = false;
  const Scene scene = GenerateScene(so, 2);
  const Renderer renderer(scene, RenderOptions{});
  const Camera cam = TestCamera(512, 600);
  const Pose pose{LookDown(0, 0, 0), V3(0, 0, 90)};
  const GeometryMaps m = renderer.RenderGeometry(cam, pose);
  // Every roof face's centroid seen from above is that roof face, at the
  // right depth (roofs are never hidden in a nadir view without trees,
  // except under a higher neighbour's roof, which does not happen here).
  int checked = 0;
  for (const RoofPlane& rp : ExtractRoofPlanes(scene.city)) {
    V3 c = V3::Zero();
    for (const V3& p : rp.polygon.exterior) c += p;
    c /= rp.polygon.exterior.size();
    const auto q = Project(cam, pose, c);
    if (!q || q->minCoeff() < 0 || q->x() >= 512 || q->y() >= 512) continue;
    const int f = m.face.at<int>(int(q->y()), int(q->x()));
    ASSERT_GE(f, 0);
    const FaceInfo& fi = renderer.faces()[f];
    EXPECT_EQ(fi.building, rp.building);
    EXPECT_EQ(fi.kind, FaceKind::kRoof);
    EXPECT_NEAR(m.depth.at<float>(int(q->y()), int(q->x())), (pose.R * (c - pose.C)).z(), 0.6);
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

// On a slope the terrain seen in every pixel lies at the slope's height
// there: flat terrain at the origin's height would be off by up to 4 m at
// the image corners of this view.
void ExpectTerrainAtItsHeight(const Eigen::Vector2d& slope, double relief) {
  SceneOptions so;
  so.extent_x = so.extent_y = 80;
  so.building_count = 4;
  so.ground_slope = slope;
  so.terrain_relief_m = relief;
  const Scene scene = GenerateScene(so, 5);
  const Renderer renderer(scene, RenderOptions{});
  const Camera cam = TestCamera(256, 300);
  const Pose pose{LookDown(20, 10, -5), V3(4, -3, 90)};
  const GeometryMaps m = renderer.RenderGeometry(cam, pose);
  int checked = 0;
  double worst = 0;
  for (int y = 0; y < cam.height; y += 7)
    for (int x = 0; x < cam.width; x += 7) {
      if (m.face.at<int>(y, x) != 0) continue;  // face 0: the terrain
      const double depth = m.depth.at<float>(y, x);
      const V3 ray((x + 0.5 - cam.cx) / cam.fx, (y + 0.5 - cam.cy) / cam.fy, 1);
      const V3 X = pose.C + pose.R.transpose() * (depth * ray);
      worst = std::max(worst, std::abs(X.z() - scene.ground.HeightAt(X.head<2>())));
      ++checked;
    }
  EXPECT_GT(checked, 300);
  EXPECT_LT(worst, 0.02);
}

TEST(Renderer, TerrainFollowsTheSlope) { ExpectTerrainAtItsHeight({0.06, -0.05}, 0); }

// Over hills the ray meets the curved ground, not the plane under it (off
// by metres here), with the slope as well.
TEST(Renderer, TerrainFollowsTheHills) { ExpectTerrainAtItsHeight({0.03, 0.02}, 15); }

}  // namespace
}  // namespace sim
}  // namespace roofsweep
