#include "io/core/crs_transform.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "algorithms/core/error.h"

namespace roofsweep {
namespace {

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Reference values from PROJ 9.1.1's own command-line tool:
//   echo "391800 5819000 50" | cs2cs -d 9 EPSG:25833 EPSG:25832
//   -> 798922.616786730 5826932.150407154 50.000000000
//   echo "391800 5819000 50" | cs2cs -d 9 EPSG:25833 EPSG:4979
//   -> 52.510368962 13.405654419 50.000000000   (latitude first in EPSG)
const Eigen::Vector3d kBerlin(391800.0, 5819000.0, 50.0);

TEST(CrsTransform, Utm33ToUtm32MatchesCs2cs) {
  const CrsTransform t("EPSG:25833", "EPSG:25832");
  const Eigen::Vector3d p = t.Forward(kBerlin);
  EXPECT_NEAR(p.x(), 798922.616786730, 1e-6);
  EXPECT_NEAR(p.y(), 5826932.150407154, 1e-6);
  EXPECT_NEAR(p.z(), 50.0, 1e-9);
  EXPECT_EQ(t.source_kind(), CrsKind::kProjected);
  EXPECT_EQ(t.target_kind(), CrsKind::kProjected);
  EXPECT_LT((t.Inverse(p) - kBerlin).norm(), 1e-6);
}

TEST(CrsTransform, GeographicTargetIsLongitudeFirst) {
  for (const char* target : {"EPSG:4979", "EPSG:4326"}) {
    const CrsTransform t("EPSG:25833", target);
    const Eigen::Vector3d g = t.Forward(kBerlin);
    EXPECT_NEAR(g.x(), 13.405654419, 1e-9) << target;
    EXPECT_NEAR(g.y(), 52.510368962, 1e-9) << target;
    // ETRS89 -> WGS 84 is the null transformation; a 2D target is promoted
    // to 3D, so the height stays ellipsoidal instead of being dropped.
    EXPECT_NEAR(g.z(), 50.0, 1e-6) << target;
  }
}

TEST(CrsTransform, OwnGeographicKeepsTheEllipsoid) {
  const CrsTransform t = CrsTransform::ToOwnGeographic3D("EPSG:25833");
  EXPECT_NEAR(t.source_semi_major(), 6378137.0, 1e-6);
  EXPECT_NEAR(1.0 / t.source_flattening(), 298.257222101, 1e-6);
  EXPECT_NEAR(t.Forward(kBerlin).y(), 52.510368962, 1e-9);
}

TEST(CrsTransform, AreaOfInterestStillGivesTheSameNumbers) {
  CrsTransformOptions o;
  o.area_of_interest = Eigen::Vector4d(13.3, 52.4, 13.5, 52.6);
  const CrsTransform t("EPSG:25833", "EPSG:25832", o);
  EXPECT_NEAR(t.Forward(kBerlin).x(), 798922.616786730, 1e-6);
}

TEST(CrsTransform, BallparkHeightStepIsRefused) {
  // cs2cs passes the heights through unchanged here (no GCG2016 grid).
  const std::string msg = ErrorOf([] { CrsTransform("EPSG:25833", "EPSG:25833+7837"); });
  EXPECT_NE(msg.find("ballpark"), std::string::npos) << msg;
  EXPECT_NE(msg.find("EPSG:25833+7837"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

TEST(CrsTransform, UnknownCrsIsNamedOnOneLine) {
  const std::string msg = ErrorOf([] { CrsTransform("EPSG:25833", "EPSG:999999"); });
  EXPECT_EQ(msg.rfind("CRS 'EPSG:999999': unknown", 0), 0u) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_NE(ErrorOf([] { CrsTransform("nonsense", "EPSG:4326"); }).find("'nonsense'"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { CrsTransform::KindOf("EPSG:0"); }).find("EPSG:0"), std::string::npos);
}

TEST(CrsTransform, KindOfCompoundReportsTheHorizontalPart) {
  CrsKind h = CrsKind::kOther;
  EXPECT_EQ(CrsTransform::KindOf("EPSG:25832+7837", &h), CrsKind::kCompound);
  EXPECT_EQ(h, CrsKind::kProjected);
  EXPECT_EQ(CrsTransform::KindOf("EPSG:4978"), CrsKind::kGeocentric);
}

TEST(CrsTransform, PointOutsideTheProjectionIsAnError) {
  const CrsTransform t("EPSG:4979", "EPSG:25833");
  const std::string msg = ErrorOf([&] { t.Forward({13.4, 95.0, 0.0}); });  // latitude > 90
  EXPECT_NE(msg.find("cannot transform the point"), std::string::npos) << msg;
}

}  // namespace
}  // namespace roofsweep
