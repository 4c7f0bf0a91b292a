// CRSs of one block as its files spell them: a layer's CRS promoted to 3D,
// a compound CRS and the plain code are the same horizontal CRS.
#include "io/core/crs_identity.h"

#include <gtest/gtest.h>

namespace roofsweep {
namespace {

TEST(IdentifyCrs, APromotedCrsWithoutItsCodeIsStillIdentified) {
  OGRSpatialReference srs;
  ASSERT_EQ(srs.importFromEPSG(25832), OGRERR_NONE);
  ASSERT_EQ(srs.PromoteTo3D(nullptr), OGRERR_NONE);
  // What GDAL stores in a GeoPackage for 3D features: no top-level ID.
  ASSERT_EQ(srs.GetAuthorityCode(nullptr), nullptr);
  EXPECT_EQ(IdentifyCrs(srs), "EPSG:25832");
}

TEST(IdentifyCrs, ACrsWithNoCodeGivesNone) {
  OGRSpatialReference srs;
  ASSERT_EQ(srs.SetFromUserInput("+proj=tmerc +lat_0=0 +lon_0=9.5 +k=0.9996 +x_0=500000 "
                                 "+y_0=0 +ellps=GRS80 +units=m +no_defs"),
            OGRERR_NONE);
  EXPECT_EQ(IdentifyCrs(srs), "");
}

TEST(SameHorizontalCrs, ComparesTheHorizontalPart) {
  EXPECT_TRUE(SameHorizontalCrs("EPSG:25833", "EPSG:25833"));
  EXPECT_TRUE(SameHorizontalCrs("EPSG:25833+7837", "EPSG:25833"));
  EXPECT_FALSE(SameHorizontalCrs("EPSG:25833", "EPSG:25832"));
  EXPECT_FALSE(SameHorizontalCrs("EPSG:25833", "not a CRS"));
}

}  // namespace
}  // namespace roofsweep
