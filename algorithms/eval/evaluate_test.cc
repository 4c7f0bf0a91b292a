#include "algorithms/eval/evaluate.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "algorithms/core/error.h"
#include "algorithms/eval/eval_report.h"
#include "algorithms/eval/test_models.h"

namespace roofsweep {
namespace {

using V = Eigen::Vector3d;
using eval_test::ThreeHouses;
using eval_test::Transformed;

CityModel Shifted(const CityModel& m, const V& d) {
  return Transformed(m, [&](const V& v) { return V(v + d); });
}

TEST(Evaluate, ModelAgainstItselfIsPerfect) {
  const CityModel m = ThreeHouses();
  const auto lines = eval_test::UniqueRoofEdges(m);
  const EvalResult r = Evaluate(m, m, {}, &lines);
  EXPECT_EQ(r.roof_planes.n_reference, 7);
  EXPECT_EQ(r.roof_planes.n_result, 7);
  EXPECT_DOUBLE_EQ(*r.roof_planes.completeness, 1);
  EXPECT_DOUBLE_EQ(*r.roof_planes.correctness, 1);
  EXPECT_DOUBLE_EQ(*r.roof_planes.quality, 1);
  EXPECT_EQ(r.roof_planes.n_1_to_m + r.roof_planes.n_n_to_1 + r.roof_planes.n_n_to_m, 0);
  EXPECT_EQ(r.geometry.matched_pairs, 7);
  EXPECT_NEAR(*r.geometry.angle_median_deg, 0, 1e-6);
  EXPECT_NEAR(*r.geometry.angle_rms_deg, 0, 1e-6);
  EXPECT_NEAR(*r.geometry.vertex_rms_m, 0, 1e-9);
  EXPECT_EQ(r.geometry.vertices, 4 + 8 + 14);
  EXPECT_NEAR(*r.geometry.rmsz_m, 0, 1e-9);
  // 80 + 96 + 140 m² at 0.25 m cells.
  EXPECT_EQ(r.geometry.rmsz_cells, (80 + 96 + 140) * 16);
  EXPECT_EQ(r.geometry.rmsz_cells_result_only + r.geometry.rmsz_cells_reference_only, 0);
  EXPECT_DOUBLE_EQ(*r.buildings.completeness, 1);
  EXPECT_DOUBLE_EQ(*r.buildings.correctness, 1);
  EXPECT_DOUBLE_EQ(*r.buildings.roof_type_agreement, 1);
  EXPECT_EQ(r.buildings.roof_type_compared, 3);
  EXPECT_NEAR(*r.lines3d.precision, 1, 1e-12);
  EXPECT_NEAR(*r.lines3d.completeness, 1, 1e-12);
  EXPECT_NEAR(*r.lines3d.roof_edge_completeness, 1, 1e-12);
  for (const auto& p : r.reference_planes) {
    EXPECT_TRUE(p.true_positive);
    EXPECT_NEAR(p.overlap_fraction, 1, 1e-9);
  }
}

TEST(Evaluate, EmptyResultAndEmptyReference) {
  const CityModel m = ThreeHouses();
  const EvalResult r = Evaluate(CityModel{}, m, {});
  EXPECT_DOUBLE_EQ(*r.roof_planes.completeness, 0);
  EXPECT_FALSE(r.roof_planes.correctness.has_value());  // 0 of 0 result planes
  EXPECT_DOUBLE_EQ(*r.roof_planes.quality, 0);
  EXPECT_EQ(r.roof_planes.n_result, 0);
  EXPECT_FALSE(r.geometry.angle_rms_deg.has_value());
  EXPECT_FALSE(r.geometry.rmsz_m.has_value());
  EXPECT_DOUBLE_EQ(*r.buildings.completeness, 0);
  EXPECT_FALSE(r.buildings.correctness.has_value());

  const EvalResult e = Evaluate(m, CityModel{}, {});
  EXPECT_FALSE(e.roof_planes.completeness.has_value());
  EXPECT_DOUBLE_EQ(*e.roof_planes.correctness, 0);

  const EvalResult both = Evaluate(CityModel{}, CityModel{}, {});
  EXPECT_FALSE(both.roof_planes.quality.has_value());
}

// Shifts along x by s. Expected overlaps, each plane with its own copy:
// box roof 10 m long: 1 - s/10; gable planes 12 m long: 1 - s/12; hip
// trapezoids (eaves 14, ridge 4, depth 5): (45 - 5 s) / 45 for s <= 4; hip
// end triangles (base 10, depth 5): (5 - s)² / 25.
TEST(Evaluate, ShiftedCopiesDropAsTheOverlapsSay) {
  const CityModel m = ThreeHouses();
  struct Case {
    double s;
    int tp;  // planes with overlap >= 50 %
    int buildings_tp;
  };
  for (const Case c : {Case{0.5, 7, 3}, Case{2, 5, 3}, Case{10, 0, 0}}) {
    SCOPED_TRACE("shift " + std::to_string(c.s));
    const EvalResult r = Evaluate(Shifted(m, V(c.s, 0, 0)), m, {});
    EXPECT_EQ(r.roof_planes.tp_reference, c.tp);
    EXPECT_EQ(r.roof_planes.tp_result, c.tp);
    EXPECT_NEAR(*r.roof_planes.completeness, c.tp / 7.0, 1e-12);
    EXPECT_NEAR(*r.roof_planes.correctness, c.tp / 7.0, 1e-12);
    EXPECT_NEAR(*r.roof_planes.quality, c.tp / (c.tp + 2.0 * (7 - c.tp)), 1e-12);
    EXPECT_EQ(r.buildings.tp_reference, c.buildings_tp);
    const auto& p = r.reference_planes;
    if (c.s < 5) {
      const double expected[7] = {1 - c.s / 10,
                                  1 - c.s / 12,
                                  1 - c.s / 12,
                                  (45 - 5 * c.s) / 45,
                                  std::pow(5 - c.s, 2) / 25,
                                  (45 - 5 * c.s) / 45,
                                  std::pow(5 - c.s, 2) / 25};
      for (int i = 0; i < 7; ++i)
        if (p[i].true_positive) {
          EXPECT_NEAR(p[i].overlap_fraction, expected[i], 1e-9) << "plane " << i;
          EXPECT_GE(expected[i], 0.5);
        } else {
          EXPECT_LT(expected[i], 0.5) << "plane " << i;
        }
    }
  }
}

TEST(Evaluate, ShiftedBoxVertexRmsAndRmsz) {
  CityModel m;
  m.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 30, 6));
  m.buildings.push_back(eval_test::Gable("G", 40, 0, 12, 8, 30, 6, 3));
  EvalOptions o;
  o.gsd_m = 0.1;
  {
    // Box: two corners on the reference outline, two 0.5 m off. Gable
    // rectangles alike. RMS = sqrt(2 * 0.25 / 4).
    const EvalResult r = Evaluate(Shifted(m, V(0.5, 0, 0)), m, o);
    EXPECT_NEAR(*r.geometry.vertex_rms_m, std::sqrt(0.125), 1e-9);
    EXPECT_NEAR(*r.geometry.vertex_rms_gsd, std::sqrt(0.125) / 0.1, 1e-7);
    // Half the vertices on the outline, half 0.5 m off.
    EXPECT_NEAR(*r.geometry.vertex_median_m, 0.25, 1e-9);
    EXPECT_NEAR(*r.geometry.vertex_within_2gsd, 0.5, 1e-9);
    // Flat roof and a gable shifted along its ridge: same heights where both exist.
    EXPECT_NEAR(*r.geometry.rmsz_m, 0, 1e-9);
    EXPECT_EQ(r.geometry.rmsz_cells, (76 + 92) * 16);  // (10-0.5)*8 + (12-0.5)*8
  }
  {
    const EvalResult r = Evaluate(Shifted(m, V(2, 0, 0)), m, o);
    EXPECT_NEAR(*r.geometry.vertex_rms_m, std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(*r.geometry.vertex_within_2gsd, 0.5, 1e-9);
  }
}

// A result face matched to A runs past it over neighbour B and over open
// ground, and has a notch cut into A: each vertex is told by where it lies
// (the tail of the vertex RMS, as `eval` prints it).
TEST(Evaluate, VerticesAreToldByWhereTheyLie) {
  CityModel truth;
  truth.buildings = {eval_test::Box("A", 0, 0, 10, 10, 0, 5),
                     eval_test::Box("B", 10, 0, 10, 10, 0, 5)};
  Building face;
  face.id = "R";
  Polygon3 roof;
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{-1, 1}, {12, 1}, {12, 9}, {5, 5}, {-1, 9}})
    roof.exterior.push_back(V(x, y, 5));
  face.surfaces.push_back({SurfaceType::kRoof, "", {roof}});
  CityModel result;
  result.buildings = {face};
  EvalOptions o;
  o.gsd_m = 0.05;
  o.keep_vertices = true;
  const EvalResult r = Evaluate(result, truth, o);
  ASSERT_EQ(r.geometry.matched_pairs, 1);
  const auto& n = r.geometry.vertex_place_count;
  EXPECT_EQ(n[static_cast<int>(VertexPlace::kOnOutline)], 0);
  EXPECT_EQ(n[static_cast<int>(VertexPlace::kInside)], 1);           // the notch (5, 5)
  EXPECT_EQ(n[static_cast<int>(VertexPlace::kOverAnotherRoof)], 2);  // x = 12, over B
  EXPECT_EQ(n[static_cast<int>(VertexPlace::kOverNoRoof)], 2);       // x = -1
  const auto& s2 = r.geometry.vertex_place_sum2;
  // 5 m off: counted, but beyond the RMS's 3 m cut, so not in its squares.
  EXPECT_NEAR(s2[static_cast<int>(VertexPlace::kInside)], 0, 1e-9);
  EXPECT_NEAR(s2[static_cast<int>(VertexPlace::kOverAnotherRoof)], 2 * 4, 1e-9);
  EXPECT_NEAR(s2[static_cast<int>(VertexPlace::kOverNoRoof)], 2 * 1, 1e-9);
  ASSERT_EQ(r.vertices.size(), 5u);
  for (const VertexRecord& v : r.vertices) {
    EXPECT_NEAR(v.position.z(), 5, 1e-9);
    EXPECT_EQ(r.reference_planes[v.reference_plane].building_id, "A");
    EXPECT_EQ(r.result_planes[v.result_plane].building_id, "R");
  }
  // On A's outline (the result is A itself): all on it, none kept unasked.
  o.keep_vertices = false;
  const EvalResult same = Evaluate(truth, truth, o);
  EXPECT_EQ(same.geometry.vertex_place_count[static_cast<int>(VertexPlace::kOnOutline)], 8);
  EXPECT_TRUE(same.vertices.empty());
  const nlohmann::json j = ToJson(r);
  EXPECT_EQ(j["geometry"]["vertex_places"]["over_no_roof"]["count"], 2);
  EXPECT_NE(FormatTable(r).find("past it, over another roof"), std::string::npos);
}

TEST(Evaluate, HeightOffsetShowsInRmszOnly) {
  const CityModel m = ThreeHouses();
  const EvalResult r = Evaluate(Shifted(m, V(0, 0, 0.3)), m, {});
  EXPECT_DOUBLE_EQ(*r.roof_planes.quality, 1);
  EXPECT_NEAR(*r.geometry.vertex_rms_m, 0, 1e-9);
  EXPECT_NEAR(*r.geometry.angle_rms_deg, 0, 1e-6);
  EXPECT_NEAR(*r.geometry.rmsz_m, 0.3, 1e-5);
  EXPECT_NEAR(*r.geometry.dz_mean_m, 0.3, 1e-5);
}

TEST(Evaluate, TiltedCopyShowsTheTiltAsAngleError) {
  // Box and gable (ridge along x) rotated 5° about an x axis: every roof
  // normal is perpendicular to the axis, so each turns by exactly 5°.
  CityModel m;
  m.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 30, 6));
  m.buildings.push_back(eval_test::Gable("G", 40, 0, 12, 8, 30, 6, 3));
  const double t = 5 * M_PI / 180;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(t, V::UnitX()).toRotationMatrix();
  const V c(25, 4, 36);
  const EvalResult r =
      Evaluate(Transformed(m, [&](const V& v) { return V(c + R * (v - c)); }), m, {});
  EXPECT_DOUBLE_EQ(*r.roof_planes.completeness, 1);
  EXPECT_DOUBLE_EQ(*r.roof_planes.correctness, 1);
  EXPECT_NEAR(*r.geometry.angle_median_deg, 5, 1e-9);
  EXPECT_NEAR(*r.geometry.angle_rms_deg, 5, 1e-9);
  EXPECT_GT(*r.geometry.rmsz_m, 0.1);
  // Beyond the tolerance (5° allowed) nothing matches.
  EvalOptions strict;
  strict.max_normal_angle_deg = 4.9;
  EXPECT_DOUBLE_EQ(
      *Evaluate(Transformed(m, [&](const V& v) { return V(c + R * (v - c)); }), m, strict)
           .roof_planes.completeness,
      0);
}

TEST(Evaluate, OneMissingRoofPlane) {
  const CityModel m = ThreeHouses();
  CityModel missing = m;
  auto& surfaces = missing.buildings[1].surfaces;  // the gable
  for (auto it = surfaces.rbegin(); it != surfaces.rend(); ++it)
    if (it->type == SurfaceType::kRoof) {
      surfaces.erase(std::next(it).base());
      break;
    }
  const EvalResult r = Evaluate(missing, m, {});
  EXPECT_EQ(r.roof_planes.n_result, 6);
  EXPECT_NEAR(*r.roof_planes.completeness, 6.0 / 7.0, 1e-12);
  EXPECT_DOUBLE_EQ(*r.roof_planes.correctness, 1);
  EXPECT_NEAR(*r.roof_planes.quality, 6.0 / 7.0, 1e-12);
  EXPECT_FALSE(r.reference_planes[2].true_positive);  // the gable's north plane
}

TEST(Evaluate, LargePlanesAreAlsoScoredAlone) {
  // A 3 x 3 m shed missed and a 2 x 3 m false roof found count in the
  // figures over all planes, not in those over planes of 10 m² or more.
  CityModel truth = ThreeHouses(), result = ThreeHouses();
  truth.buildings.push_back(eval_test::Box("B_shed", 120, 0, 3, 3, 30, 2.5));
  result.buildings.push_back(eval_test::Box("B_false", 140, 0, 2, 3, 30, 4));
  const EvalResult r = Evaluate(result, truth, {});
  const RoofPlaneScores& p = r.roof_planes;
  EXPECT_NEAR(*p.completeness, 7.0 / 8.0, 1e-12);
  EXPECT_NEAR(*p.correctness, 7.0 / 8.0, 1e-12);
  EXPECT_EQ(p.n_reference_large, 7);
  EXPECT_EQ(p.n_result_large, 7);
  EXPECT_DOUBLE_EQ(*p.completeness_large, 1);
  EXPECT_DOUBLE_EQ(*p.correctness_large, 1);
  EvalOptions o;
  o.large_plane_m2 = 5;  // both small planes count again
  const EvalResult r5 = Evaluate(result, truth, o);
  EXPECT_NEAR(*r5.roof_planes.completeness_large, 7.0 / 8.0, 1e-12);
  EXPECT_NEAR(*r5.roof_planes.correctness_large, 7.0 / 8.0, 1e-12);
  o.large_plane_m2 = 1e6;  // no plane that large: undefined, not 0 or 1
  const EvalResult none = Evaluate(result, truth, o);
  EXPECT_FALSE(none.roof_planes.completeness_large.has_value());
  EXPECT_FALSE(none.roof_planes.correctness_large.has_value());
}

// Buildings match in plan; their roof tops are compared apart, so that a
// garage roofed metres too high (at the tree crown over it) is seen.
TEST(Evaluate, MatchedBuildingsAreComparedByTheirRoofTops) {
  CityModel truth, result;
  truth.buildings.push_back(eval_test::Box("A", 0, 0, 10, 8, 0, 6));
  truth.buildings.push_back(eval_test::Box("B", 20, 0, 4, 3, 0, 3));
  result.buildings.push_back(eval_test::Box("a", 0, 0, 10, 8, 0, 6.5));
  result.buildings.push_back(eval_test::Box("b", 20, 0, 4, 3, 0, 10));
  const EvalResult r = Evaluate(result, truth, {});
  EXPECT_DOUBLE_EQ(*r.buildings.completeness, 1);
  EXPECT_EQ(r.buildings.top_compared, 2);
  EXPECT_EQ(r.buildings.top_off, 1);
  ASSERT_TRUE(r.buildings.top_rms_m.has_value());
  EXPECT_NEAR(*r.buildings.top_rms_m, std::sqrt((0.5 * 0.5 + 7.0 * 7.0) / 2), 1e-9);
  EXPECT_NE(FormatTable(r).find("roof top within 2.0 m"), std::string::npos) << FormatTable(r);
  EXPECT_NE(FormatTable(r).find("1 of 2 found, RMS 4.96 m"), std::string::npos) << FormatTable(r);
  EXPECT_EQ(ToJson(r)["buildings"]["top_off"], 1);
  EvalOptions o;
  o.building_top_tolerance_m = 8;
  EXPECT_EQ(Evaluate(result, truth, o).buildings.top_off, 0);
}

TEST(Evaluate, WrongNormalsDoNotMatchButFootprintsDo) {
  CityModel flat, gable;
  flat.buildings.push_back(eval_test::Box("B", 0, 0, 12, 8, 0, 6));
  gable.buildings.push_back(eval_test::Gable("B", 0, 0, 12, 8, 0, 6, 3));
  const EvalResult r = Evaluate(flat, gable, {});
  EXPECT_DOUBLE_EQ(*r.roof_planes.completeness, 0);
  EXPECT_DOUBLE_EQ(*r.roof_planes.correctness, 0);
  EXPECT_DOUBLE_EQ(*r.buildings.completeness, 1);
  EXPECT_DOUBLE_EQ(*r.buildings.roof_type_agreement, 0);
  const std::map<std::pair<int, int>, int> pairs = {{{roof_type::kGabled, roof_type::kFlat}, 1}};
  EXPECT_EQ(r.buildings.roof_type_pairs, pairs);
  EXPECT_NE(FormatTable(r).find("gabled as flat"), std::string::npos);
  const nlohmann::json j = ToJson(r)["buildings"]["roof_type_pairs"];
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["reference"], "gabled");
  EXPECT_EQ(j[0]["result"], "flat");
  EXPECT_EQ(j[0]["count"], 1);
  // Under-segmentation is still seen: one result plane over two reference planes.
  EXPECT_EQ(r.roof_planes.n_n_to_1, 1);
  // Each gable face lies wholly under the flat plane, which lies half over
  // each face: both sides are unmatched for their slope.
  EXPECT_EQ(r.roof_planes.false_result.count, (std::array<int, kUnmatchedKinds>{0, 1, 0, 0}));
  EXPECT_EQ(r.roof_planes.missed_reference.count, (std::array<int, kUnmatchedKinds>{0, 2, 0, 0}));
  EXPECT_NEAR(r.roof_planes.false_result.area_m2[1], 96, 1e-9);
}

TEST(Evaluate, UnmatchedPlanesAreToldByWhatCoversThem) {
  // Three flat roofs of 4 x 8 m in a row against one of 12 x 8 m over them.
  CityModel row, whole, away;
  for (int i = 0; i < 3; ++i)
    row.buildings.push_back(eval_test::Box("R" + std::to_string(i), 4.0 * i, 0, 4, 8, 0, 6));
  whole.buildings.push_back(eval_test::Box("W", 0, 0, 12, 8, 0, 6));
  // The whole roof as a result lies across the row (a terraced row no
  // image parts): each unit holds a third, all at its slope.
  const EvalResult across = Evaluate(whole, row, {});
  EXPECT_EQ(across.roof_planes.tp_reference, 3);
  EXPECT_EQ(across.roof_planes.tp_result, 0);
  EXPECT_EQ(across.result_planes[0].unmatched, UnmatchedKind::kSeveralAtItsSlope);
  EXPECT_EQ(across.roof_planes.false_result.count, (std::array<int, kUnmatchedKinds>{0, 0, 1, 0}));
  EXPECT_NEAR(across.roof_planes.false_result.area_m2[2], 96, 1e-9);
  // The row as a result holds the whole reference roof in pieces.
  const EvalResult pieces = Evaluate(row, whole, {});
  EXPECT_EQ(pieces.roof_planes.tp_result, 3);
  EXPECT_EQ(pieces.reference_planes[0].unmatched, UnmatchedKind::kSeveralAtItsSlope);
  EXPECT_EQ(pieces.roof_planes.missed_reference.count,
            (std::array<int, kUnmatchedKinds>{0, 0, 1, 0}));
  // A flat roof over a hip roof: the four faces together cover it, none
  // holds half of it, none is at its slope.
  CityModel hip, flat;
  hip.buildings.push_back(eval_test::Hip("H", 0, 0, 14, 10, 0, 6, 4));
  flat.buildings.push_back(eval_test::Box("F", 0, 0, 14, 10, 0, 6));
  const EvalResult flat_on_hip = Evaluate(flat, hip, {});
  EXPECT_EQ(flat_on_hip.result_planes[0].unmatched, UnmatchedKind::kSeveral);
  EXPECT_STREQ(UnmatchedKindKey(UnmatchedKind::kSeveral), "several");
  // A roof two thirds off the reference, another wholly off it.
  away.buildings.push_back(eval_test::Box("A", 8, 0, 12, 8, 0, 6));
  away.buildings.push_back(eval_test::Box("B", 40, 0, 12, 8, 0, 6));
  const EvalResult off = Evaluate(away, whole, {});
  EXPECT_EQ(off.roof_planes.false_result.count, (std::array<int, kUnmatchedKinds>{2, 0, 0, 0}));
  EXPECT_EQ(off.roof_planes.missed_reference.count, (std::array<int, kUnmatchedKinds>{1, 0, 0, 0}));
  const std::string table = FormatTable(off);
  EXPECT_NE(table.find("off the reference roofs"), std::string::npos);
  EXPECT_NE(table.find("not covered by the result"), std::string::npos);
  const nlohmann::json j = ToJson(off)["roof_planes"];
  EXPECT_EQ(j["false_result"]["uncovered"]["count"], 2);
  EXPECT_NEAR(j["false_result"]["uncovered"]["area_m2"].get<double>(), 192, 1e-9);
  EXPECT_EQ(j["missed_reference"]["several"]["count"], 0);
  EXPECT_EQ(j["missed_reference"]["several_at_its_slope"]["count"], 0);
}

TEST(Evaluate, OverAndUnderSegmentation) {
  // A low gable with an off-centre ridge (7.1° and 3.1° pitch, 30 % / 70 %
  // of the plan) against a flat roof: all within the 10° tolerance.
  CityModel flat, low;
  flat.buildings.push_back(eval_test::Box("B", 0, 0, 12, 8, 0, 6));
  low.buildings.push_back(eval_test::Gable("B", 0, 0, 12, 8, 0, 6, 0.3, 0.3));
  const EvalResult over = Evaluate(low, flat, {});
  EXPECT_EQ(over.roof_planes.n_1_to_m, 1);
  EXPECT_EQ(over.roof_planes.n_n_to_1, 0);
  EXPECT_EQ(over.roof_planes.n_n_to_m, 0);
  EXPECT_DOUBLE_EQ(*over.roof_planes.completeness, 1);  // 70 % by one plane
  EXPECT_DOUBLE_EQ(*over.roof_planes.correctness, 1);
  const EvalResult under = Evaluate(flat, low, {});
  EXPECT_EQ(under.roof_planes.n_1_to_m, 0);
  EXPECT_EQ(under.roof_planes.n_n_to_1, 1);
  EXPECT_DOUBLE_EQ(*under.roof_planes.completeness, 1);
  EXPECT_DOUBLE_EQ(*under.roof_planes.correctness, 1);
  // A ridge off-centre the other way in the result: 2 against 2 crosswise.
  CityModel other;
  other.buildings.push_back(eval_test::Gable("B", 0, 0, 12, 8, 0, 6, 0.3, 0.7));
  const EvalResult nm = Evaluate(other, low, {});
  EXPECT_EQ(nm.roof_planes.n_n_to_m, 1);
}

TEST(Evaluate, VerticalRoofPolygonIsLeftOutAndCounted) {
  CityModel m = ThreeHouses();
  CityModel with_wall_as_roof = m;
  with_wall_as_roof.buildings[0].surfaces.push_back(
      {SurfaceType::kRoof,
       "mislabelled",
       {{{V(0, 0, 30), V(10, 0, 30), V(10, 0, 36), V(0, 0, 36)}, {}}}});
  const EvalResult r = Evaluate(with_wall_as_roof, m, {});
  EXPECT_EQ(r.result_input.vertical, 1);
  EXPECT_EQ(r.roof_planes.n_result, 7);
  EXPECT_DOUBLE_EQ(*r.roof_planes.quality, 1);
  EXPECT_NEAR(*r.geometry.rmsz_m, 0, 1e-9);
}

TEST(Evaluate, CourtyardHole) {
  CityModel holed, solid;
  solid.buildings.push_back(eval_test::Box("B", 0, 0, 10, 8, 0, 6));
  holed = solid;
  for (auto& s : holed.buildings[0].surfaces)
    if (s.type == SurfaceType::kRoof)
      s.polygons[0].holes.push_back({V(2, 2, 6), V(2, 6, 6), V(8, 6, 6), V(8, 2, 6)});
  const EvalResult self = Evaluate(holed, holed, {});
  EXPECT_DOUBLE_EQ(*self.roof_planes.quality, 1);
  EXPECT_NEAR(self.reference_planes[0].plan_area, 56, 1e-9);
  EXPECT_EQ(self.geometry.rmsz_cells, 56 * 16);
  // The solid roof covers all of the holed one; 56 of its 80 m² are covered.
  const EvalResult r = Evaluate(solid, holed, {});
  EXPECT_NEAR(r.reference_planes[0].overlap_fraction, 1, 1e-9);
  EXPECT_NEAR(r.result_planes[0].overlap_fraction, 0.7, 1e-9);
  EXPECT_DOUBLE_EQ(*r.roof_planes.quality, 1);
}

TEST(Evaluate, BadOptionsThrow) {
  const CityModel m = ThreeHouses();
  EvalOptions o;
  o.plane_overlap_fraction = 0;
  EXPECT_THROW(Evaluate(m, m, o), Error);
  o = {};
  o.rmsz_grid_m = -1;
  EXPECT_THROW(Evaluate(m, m, o), Error);
  o = {};
  o.large_plane_m2 = std::nan("");
  EXPECT_THROW(Evaluate(m, m, o), Error);
}

}  // namespace
}  // namespace roofsweep
