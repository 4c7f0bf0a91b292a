#include "algorithms/sweep/sweep_half_planes.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>

#include "algorithms/core/error.h"
#include "algorithms/sweep/test_scene.h"

namespace roofsweep {
namespace {

using sweep_test::Quad;
using sweep_test::TestScene;

constexpr double kDeg = M_PI / 180.0;
const Segment3 kRidge{{-5, 0, 10}, {5, 0, 10}};

// A face attached to the ridge on side `side` (+1: +y), falling at `pitch_deg`
// over a horizontal run of `run` metres, `extend` metres longer than the
// line at both ends.
Quad Face(int side, double pitch_deg, double run, bool textured, uint32_t seed, double extend = 0) {
  Quad q;
  q.origin = kRidge.a - Eigen::Vector3d(extend, 0, 0);
  q.u = kRidge.b - kRidge.a + Eigen::Vector3d(2 * extend, 0, 0);
  q.v = Eigen::Vector3d(0, side * run, -run * std::tan(pitch_deg * kDeg));
  q.textured = textured;
  q.seed = seed;
  return q;
}

const HalfPlane& SideOf(const std::vector<HalfPlane>& r, int side) {
  return r.at(side > 0 ? 0 : 1);
}

// Sweeps the ridge (results 0, 1) and any further lines.
std::vector<HalfPlane> Sweep(const TestScene& scene, const Block& block,
                             const SweepOptions& options = SweepOptions(),
                             const std::vector<Segment3>& more_lines = {}) {
  NullProgress progress;
  std::vector<SweepLine> lines = {{kRidge, {}}};
  for (const Segment3& s : more_lines) lines.push_back({s, {}});
  return SweepHalfPlanes(block, sweep_test::RenderAll(scene, block), lines, options, progress);
}

// The lower edge of a face (its eave), as a 3D line.
Segment3 Eave(const Quad& q) { return Segment3{q.origin + q.v, q.origin + q.u + q.v}; }

// A gable roof: both textured faces are found at -pitch, within 1 degree
// (the paper reports better than 2).
TEST(SweepHalfPlanes, GableRidgeFindsBothPitches) {
  TestScene scene;
  scene.quads = {Face(1, 30, 6, true, 3), Face(-1, 40, 6, true, 4)};
  const Block block = sweep_test::FourViewBlock();
  const auto r = Sweep(scene, block);
  ASSERT_EQ(r.size(), 2u);
  for (int side : {1, -1}) {
    const HalfPlane& h = SideOf(r, side);
    SCOPED_TRACE(side);
    EXPECT_TRUE(h.accepted) << h.reason;
    EXPECT_NEAR(h.theta_deg, side > 0 ? -30.0 : -40.0, 1.0);
    EXPECT_GE(h.similarity, 0.4);
    EXPECT_LE(h.curvature, -4.0);
    EXPECT_EQ(h.views, 3);
    EXPECT_GE(h.points, 20);
    // One Sim value per coarse angle over the swept range, both ends
    // included, at most coarse_step_deg apart.
    const SweepOptions o;
    const double range = o.theta_max_deg - o.theta_min_deg;
    EXPECT_EQ(h.profile.size(), static_cast<size_t>(std::ceil(range / o.coarse_step_deg)) + 1);
    // The plane agrees with theta and contains the line.
    EXPECT_NEAR(h.plane.head<3>().dot(kRidge.a) + h.plane(3), 0, 1e-9);
  }
}

// Under heavy sensor noise a textured face's Sim stays low (0.09 here
// against 0.64 at a quarter of the noise), but its peak still stands six
// times above the median of its profile. Calibrated on the block's clear
// peaks (here a handful of sides instead of 30), the candidate threshold
// falls with the noise: the face is a candidate, at the right angle. The
// untextured face on the other side is not.
TEST(SweepHalfPlanes, TheCandidateThresholdFallsWithTheNoise) {
  TestScene scene;
  scene.quads = {Face(1, 30, 6, true, 3, 3), Face(-1, 40, 6, false, 4, 3)};
  scene.noise_sigma = 0.08;  // 20 times the default
  const std::vector<Segment3> eaves = {Eave(scene.quads[0]), Eave(scene.quads[1])};
  const Block block = sweep_test::FourViewBlock();
  SweepOptions o;
  o.calibration_min_sides = 1;
  const auto r = Sweep(scene, block, o, eaves);
  const HalfPlane& face = SideOf(r, 1);
  EXPECT_LT(face.similarity, o.candidate_min_similarity);
  EXPECT_GE(face.peak_ratio, o.calibration_peak_ratio);
  EXPECT_TRUE(face.candidate) << face.reason;
  EXPECT_FALSE(face.accepted);
  EXPECT_NEAR(face.theta_deg, -30.0, 2.0);
  EXPECT_FALSE(SideOf(r, -1).candidate);
  SweepOptions fixed = o;
  fixed.calibration_peak_ratio = 0;
  EXPECT_FALSE(SideOf(Sweep(scene, block, fixed, eaves), 1).candidate);
  // The verification's score threshold falls with it, by the root.
  const double scale = CandidateThreshold(r, o) / o.candidate_min_similarity;
  EXPECT_LT(scale, 1.0);
  EXPECT_NEAR(ScoreThresholdAtImageQuality(0.3, r, o), 0.3 * std::sqrt(scale), 1e-12);
  EXPECT_EQ(ScoreThresholdAtImageQuality(0.3, r, fixed), 0.3);
  // Noisy enough for the wider window, which averages the noise over more
  // pixels: the face's peak stands further above its profile (measured:
  // 6.1 -> 8.3 times its median; Sim itself hardly moves, 0.094 -> 0.091),
  // at the same angle, and the untextured face stays out.
  EXPECT_TRUE(WantsWiderWindow(r, o));
  SweepOptions wide = o;
  wide.ncc_radius = o.wide_ncc_radius;
  EXPECT_FALSE(WantsWiderWindow(r, wide));  // already wide
  const auto w = Sweep(scene, block, wide, eaves);
  EXPECT_GT(SideOf(w, 1).peak_ratio, 1.2 * face.peak_ratio);
  EXPECT_NEAR(SideOf(w, 1).theta_deg, -30.0, 2.0);
  EXPECT_FALSE(SideOf(w, -1).candidate);
  SweepOptions never = o;
  never.wide_ncc_radius = o.ncc_radius;
  EXPECT_FALSE(WantsWiderWindow(r, never));
  // At the default noise the thresholds stay the fixed ones.
  scene.noise_sigma = TestScene().noise_sigma;
  const auto clean = Sweep(scene, block, o, eaves);
  EXPECT_TRUE(SideOf(clean, 1).accepted);
  EXPECT_FALSE(SideOf(clean, -1).candidate);
  EXPECT_EQ(ScoreThresholdAtImageQuality(0.3, clean, o), 0.3);
  EXPECT_FALSE(WantsWiderWindow(clean, o));
}

// An untextured face gives no reliable maximum. The faces run on beyond the
// line: an untextured face's own outline (its verges against the ground)
// is texture on the plane and would rightly support it. The eaves are
// input lines too, as they would be in the pipeline: they bound the
// neighbourhood, which would otherwise reach the ground beyond the face.
TEST(SweepHalfPlanes, UntexturedSideIsRejected) {
  TestScene scene;
  scene.quads = {Face(1, 30, 6, true, 3, 3), Face(-1, 40, 6, false, 4, 3)};
  const std::vector<Segment3> eaves = {Eave(scene.quads[0]), Eave(scene.quads[1])};
  const Block block = sweep_test::FourViewBlock();
  const auto r = Sweep(scene, block, SweepOptions(), eaves);
  EXPECT_TRUE(SideOf(r, 1).accepted) << SideOf(r, 1).reason;
  EXPECT_NEAR(SideOf(r, 1).theta_deg, -30.0, 1.0);
  const HalfPlane& flat = SideOf(r, -1);
  EXPECT_FALSE(flat.accepted);
  EXPECT_FALSE(flat.reason.empty());
  // With a threshold low enough to take sensor noise for texture the
  // points are there, but they do not correlate across views.
  SweepOptions noisy;
  noisy.poi_canny_low = 0.5;
  noisy.poi_canny_high = 1.0;
  noisy.poi_blur_sigma = 0;
  const HalfPlane noise = SideOf(Sweep(scene, block, noisy, eaves), -1);
  EXPECT_GE(noise.points_detected, 20);
  EXPECT_FALSE(noise.accepted);
  std::cout << "untextured side, noise as texture: " << noise.reason << " (points "
            << noise.points_detected << ", theta " << noise.theta_deg << ", sim "
            << noise.similarity << ", curvature " << noise.curvature << ")\n";
  std::cout << "untextured side: " << flat.reason << " (points " << flat.points_detected
            << ", theta " << flat.theta_deg << ", sim " << flat.similarity << ", curvature "
            << flat.curvature << ")\n";
}

// A flat roof's edge over a wall: the roof side is found at 0 degrees, the
// wall side (vertical wall, ground 10 m below) has no half-plane in
// [-75, 75].
TEST(SweepHalfPlanes, EaveOverWallHasNoOuterHalfPlane) {
  TestScene scene;
  Quad roof = Face(1, 0, 8, true, 5);
  Quad wall;
  wall.origin = kRidge.a;
  wall.u = kRidge.b - kRidge.a;
  wall.v = Eigen::Vector3d(0, 0, -10);
  wall.seed = 6;
  scene.quads = {roof, wall};
  const Block block = sweep_test::FourViewBlock();
  const auto r = Sweep(scene, block);
  EXPECT_TRUE(SideOf(r, 1).accepted) << SideOf(r, 1).reason;
  EXPECT_NEAR(SideOf(r, 1).theta_deg, 0.0, 1.0);
  const HalfPlane& outer = SideOf(r, -1);
  EXPECT_FALSE(outer.accepted) << "theta " << outer.theta_deg << " sim " << outer.similarity;
  std::cout << "outer side: " << outer.reason << " (theta " << outer.theta_deg << ", sim "
            << outer.similarity << ", curvature " << outer.curvature << ")\n";
}

// A line longer than any view's footprint (no view holds both end points)
// is swept on the parts the views see.
TEST(SweepHalfPlanes, LinePartlyOutsideEveryView) {
  TestScene scene;
  // Faces 60 m long along x; the views cover x in [-40.8, 16.8] and
  // [-16.8, 40.8] at the ridge's height.
  scene.quads = {Face(1, 30, 6, true, 3, 25), Face(-1, 40, 6, true, 4, 25)};
  const Segment3 long_ridge{{-5, 0, 10}, {45, 0, 10}};
  const Block block = sweep_test::FourViewBlock();
  NullProgress progress;
  const auto r = SweepHalfPlanes(block, sweep_test::RenderAll(scene, block),
                                 {SweepLine{long_ridge, {}}}, SweepOptions(), progress);
  ASSERT_EQ(r.size(), 2u);
  for (int side : {1, -1}) {
    const HalfPlane& h = SideOf(r, side);
    SCOPED_TRACE(side);
    EXPECT_TRUE(h.accepted) << h.reason;
    EXPECT_NEAR(h.theta_deg, side > 0 ? -30.0 : -40.0, 1.0);
    EXPECT_EQ(h.views, 3);
  }
}

// The two sweeps gave the same sides, bit for bit.
void ExpectSameSides(const std::vector<HalfPlane>& a, const std::vector<HalfPlane>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].theta_deg, b[i].theta_deg);
    EXPECT_EQ(a[i].similarity, b[i].similarity);
    EXPECT_EQ(a[i].curvature, b[i].curvature);
    EXPECT_EQ(a[i].reference_view, b[i].reference_view);
    EXPECT_EQ(a[i].points, b[i].points);
    EXPECT_EQ(a[i].points_detected, b[i].points_detected);
    EXPECT_EQ(a[i].accepted, b[i].accepted);
    EXPECT_EQ(a[i].candidate, b[i].candidate);
    EXPECT_EQ(a[i].profile, b[i].profile);
  }
}

TEST(SweepHalfPlanes, DeterministicAcrossThreadCounts) {
  TestScene scene;
  scene.quads = {Face(1, 25, 6, true, 7), Face(-1, 35, 6, true, 8)};
  const Block block = sweep_test::FourViewBlock();
  const auto images = sweep_test::RenderAll(scene, block);
  // Several lines so that the sides run in parallel.
  std::vector<SweepLine> lines;
  for (int i = 0; i < 6; ++i) {
    Segment3 s = kRidge;
    s.a.x() += 0.5 * i;
    lines.push_back({s, {}});
  }
  NullProgress progress;
  const auto a = SweepHalfPlanes(block, images, lines, SweepOptions(), progress);
  std::vector<HalfPlane> b;
  tbb::task_arena one(1);
  one.execute([&] { b = SweepHalfPlanes(block, images, lines, SweepOptions(), progress); });
  ExpectSameSides(a, b);
}

TEST(SweepHalfPlanes, LinesAddedLaterGiveTheSameSidesAsASweepFromScratch) {
  TestScene scene;
  const Quad north = Face(1, 25, 6, true, 7);
  scene.quads = {north, Face(-1, 35, 6, true, 8)};
  const Block block = sweep_test::FourViewBlock();
  const auto images = sweep_test::RenderAll(scene, block);
  NullProgress progress;
  // The ridge, and a line far from it.
  std::vector<SweepLine> lines = {{kRidge, {}}, {Segment3{{-5, 150, 10}, {5, 150, 10}}, {}}};
  const auto before = SweepHalfPlanes(block, images, lines, SweepOptions(), progress);
  // A line across the north face 1.5 m from the ridge: it bounds the band.
  const double z = 10 - 1.5 * std::tan(25 * kDeg);
  lines.push_back({Segment3{{-5, 1.5, z}, {5, 1.5, z}}, {}});
  const auto scratch = SweepHalfPlanes(block, images, lines, SweepOptions(), progress);
  const auto added = SweepHalfPlanes(block, images, lines, SweepOptions(), progress, &before);
  EXPECT_NE(scratch[0].extent_m, before[0].extent_m);
  EXPECT_NE(scratch[0].points_detected, before[0].points_detected);
  ExpectSameSides(scratch, added);
}

TEST(SweepHalfPlanes, BadInputIsAnError) {
  const Block block = sweep_test::FourViewBlock();
  NullProgress progress;
  std::vector<cv::Mat> images(3, cv::Mat(480, 640, CV_32FC3, cv::Scalar::all(0.5)));
  EXPECT_THROW(SweepHalfPlanes(block, images, {}, SweepOptions(), progress), Error);
  images.push_back(cv::Mat(100, 100, CV_32FC3, cv::Scalar::all(0.5)));
  EXPECT_THROW(SweepHalfPlanes(block, images, {}, SweepOptions(), progress), Error);
  images.back() = cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(128));
  EXPECT_THROW(SweepHalfPlanes(block, images, {}, SweepOptions(), progress), Error);
  EXPECT_THROW(PrepareViewTextures(block, images, SweepOptions()), Error);
  // Views prepared for another block.
  images.back() = cv::Mat(480, 640, CV_32FC3, cv::Scalar::all(0.5));
  std::vector<ViewTexture> textures = PrepareViewTextures(block, images, SweepOptions());
  textures.back() =
      PrepareViewTexture(cv::Mat(100, 100, CV_32FC3, cv::Scalar::all(0.5)), SweepOptions());
  EXPECT_THROW(SweepHalfPlanes(block, textures, {}, SweepOptions(), progress), Error);
  textures.pop_back();
  EXPECT_THROW(SweepHalfPlanes(block, textures, {}, SweepOptions(), progress), Error);
}

TEST(SweepHalfPlanes, VerticalLineIsReportedNotSwept) {
  const Block block = sweep_test::FourViewBlock();
  NullProgress progress;
  std::vector<cv::Mat> images(4, cv::Mat(480, 640, CV_32FC3, cv::Scalar::all(0.5)));
  const auto r = SweepHalfPlanes(block, images, {SweepLine{Segment3{{0, 0, 0}, {0, 0, 5}}, {}}},
                                 SweepOptions(), progress);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_FALSE(r[0].accepted);
  EXPECT_FALSE(r[1].accepted);
  EXPECT_EQ(r[0].reason, "degenerate or near-vertical line");
}

}  // namespace
}  // namespace roofsweep
