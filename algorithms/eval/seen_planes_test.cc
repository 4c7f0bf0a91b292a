#include "algorithms/eval/seen_planes.h"

#include <gtest/gtest.h>

#include "algorithms/eval/test_models.h"

namespace roofsweep {
namespace {

// Every roof polygon of the model, seen by `n_views` views at `fraction`.
std::vector<SeenPolygon> AllSeen(const CityModel& m, int n_views, float fraction) {
  std::vector<SeenPolygon> out;
  for (const Building& b : m.buildings)
    for (const Surface& s : b.surfaces) {
      if (s.type != SurfaceType::kRoof) continue;
      for (const Polygon3& p : s.polygons) {
        SeenPolygon q;
        for (const Eigen::Vector3d& v : p.exterior) q.centroid += v;
        q.centroid /= static_cast<double>(p.exterior.size());
        q.seen.assign(n_views, fraction);
        out.push_back(q);
      }
    }
  return out;
}

TEST(ScoreSeenPlanes, PlanesSeenByFewerThanTwoViewsAreCountedApart) {
  const CityModel truth = eval_test::ThreeHouses();
  CityModel result;
  result.crs = truth.crs;
  result.buildings = {truth.buildings[2]};  // only the hip house was built
  const EvalResult e = Evaluate(result, truth, EvalOptions());
  ASSERT_EQ(e.reference_planes.size(), 7u);

  std::vector<SeenPolygon> seen = AllSeen(truth, 3, 1.0f);
  // A tree over the box: its roof seen by one view only, and half of it
  // by another (the threshold is the half).
  for (SeenPolygon& p : seen)
    if (p.centroid.x() < 20) p.seen = {1.0f, 0.2f, 0.49f};
  // Rounding of the written model moves a centroid by a millimetre.
  for (SeenPolygon& p : seen) p.centroid.x() += 0.001;

  const SeenPlaneScores s = ScoreSeenPlanes(truth, e, seen);
  EXPECT_EQ(s.unknown, 0);
  EXPECT_EQ(s.unseen, 1);
  EXPECT_EQ(s.unseen_true_positive, 0);
  EXPECT_EQ(s.seen, 6);
  EXPECT_EQ(s.seen_true_positive, 4);  // the hip's four faces
  EXPECT_NEAR(s.Completeness(), 4.0 / 6.0, 1e-12);
  for (size_t r = 0; r < e.reference_planes.size(); ++r)
    EXPECT_EQ(s.views[r], e.reference_planes[r].building == 0 ? 1 : 3) << r;

  // Records that do not match (another model) leave the planes unknown.
  std::vector<SeenPolygon> moved = seen;
  for (SeenPolygon& p : moved) p.centroid.y() += 1;
  const SeenPlaneScores u = ScoreSeenPlanes(truth, e, moved);
  EXPECT_EQ(u.unknown, 7);
  EXPECT_EQ(u.seen + u.unseen, 0);
}

}  // namespace
}  // namespace roofsweep
