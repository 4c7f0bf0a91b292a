#include "io/core/local_frame.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/TransverseMercator.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <thread>

#include "algorithms/core/error.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

constexpr double kGrs80A = 6378137.0;
constexpr double kGrs80F = 1 / 298.257222101;
const Eigen::Vector3d kOrigin(512345.0, 5400000.0, 150.0);  // ecosystem notes §5

Eigen::Matrix3d Rz(double deg) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// Independent of PROJ: GeographicLib's transverse Mercator for UTM zone 32.
struct Utm32 {
  GeographicLib::TransverseMercator tm{kGrs80A, kGrs80F, GeographicLib::Constants::UTM_k0()};
  void Reverse(const Eigen::Vector3d& p, double* lat, double* lon, double* gamma) const {
    double k = 0;
    tm.Reverse(9.0, p.x() - 500000.0, p.y(), *lat, *lon, *gamma, k);
  }
};

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(LocalFrame, NotesTestVectorUtm32) {
  const LocalFrame frame("EPSG:25832", kOrigin);
  ASSERT_TRUE(frame.HasCrs());
  const Eigen::Vector3d o = frame.ToLocal(kOrigin);
  EXPECT_LT(o.norm(), 1e-6);
  const Eigen::Vector3d cam = frame.ToLocal(kOrigin + Eigen::Vector3d(3000, 2000, 1000));
  EXPECT_NEAR(cam.x(), 3006.137, 1e-3);
  EXPECT_NEAR(cam.y(), 1994.535, 1e-3);
  EXPECT_NEAR(cam.z(), 998.981, 1e-3);
  const Eigen::Vector3d north = frame.ToLocal(kOrigin + Eigen::Vector3d(0, 100, 0));
  EXPECT_NEAR(north.x(), 0.2205, 1e-3);
  EXPECT_NEAR(north.y(), 100.042, 1e-3);
  EXPECT_NEAR(north.z(), -0.001, 1e-3);
  EXPECT_NEAR(frame.ConvergenceDeg(kOrigin), 0.1263, 5e-5);
  const FrameInfo info = frame.Info();
  EXPECT_EQ(info.crs, "EPSG:25832");
  EXPECT_NEAR(info.origin_lat, 48.7529, 1e-4);
  EXPECT_NEAR(info.origin_lon, 9.1680, 1e-4);
  EXPECT_NEAR(info.origin_h, 150.0, 1e-9);
}

TEST(LocalFrame, AgreesWithGeographicLibAlone) {
  const LocalFrame frame("EPSG:25832", kOrigin);
  const Utm32 utm;
  double lat0, lon0, gamma0;
  utm.Reverse(kOrigin, &lat0, &lon0, &gamma0);
  const GeographicLib::LocalCartesian lc(lat0, lon0, kOrigin.z(),
                                         GeographicLib::Geocentric(kGrs80A, kGrs80F));
  for (const Eigen::Vector3d& d :
       {Eigen::Vector3d(3000, 2000, 1000), Eigen::Vector3d(-20000, 15000, 50),
        Eigen::Vector3d(7000, -9000, 2500)}) {
    const Eigen::Vector3d p = kOrigin + d;
    double lat, lon, gamma;
    utm.Reverse(p, &lat, &lon, &gamma);
    Eigen::Vector3d want;
    std::vector<double> m(9);
    lc.Forward(lat, lon, p.z(), want.x(), want.y(), want.z(), m);
    EXPECT_LT((frame.ToLocal(p) - want).norm(), 1e-4) << d.transpose();
    // gamma is defined on the ellipsoid; at height h grid north turns by a
    // further ~gamma h e'² cos²(lat) / R (2.4e-7 degrees at 2.6 km).
    EXPECT_NEAR(frame.ConvergenceDeg(p), gamma, 5e-7) << d.transpose();
    EXPECT_NEAR(frame.ConvergenceDeg({p.x(), p.y(), 0.0}), gamma, 3e-8) << d.transpose();
    // Grid axes at p: ENU at p turned by the convergence, then carried into
    // the origin's ENU axes by GeographicLib's rotation.
    const Eigen::Matrix3d enu_p =
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m.data());
    const Eigen::Matrix3d want_r = enu_p * Rz(-gamma);
    EXPECT_LT((frame.GridToLocal(p) - want_r).norm(), 1e-8) << d.transpose();
  }
  EXPECT_LT((frame.GridToLocal(kOrigin) - Rz(-gamma0)).norm(), 1e-9);
}

TEST(LocalFrame, RoundTripBelowMicrometre) {
  const LocalFrame frame("EPSG:25832", kOrigin);
  double worst = 0;
  for (int i = -3; i <= 3; ++i) {
    for (int j = -3; j <= 3; ++j) {
      const Eigen::Vector3d p = kOrigin + Eigen::Vector3d(5000.0 * i, 4000.0 * j, 300.0 * (i + j));
      worst = std::max(worst, (frame.ToCrs(frame.ToLocal(p)) - p).norm());
      const Eigen::Vector3d l(1234.5 * i, -987.6 * j, 40.0 * i);
      worst = std::max(worst, (frame.ToLocal(frame.ToCrs(l)) - l).norm());
    }
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(LocalFrame, NorthingFirstCrsIsTakenEastingFirst) {
  // EPSG:31467 (Gauss-Krüger zone 3) declares northing before easting.
  const Eigen::Vector3d o(3512345.0, 5400000.0, 150.0);
  const LocalFrame frame("EPSG:31467", o);
  const Eigen::Vector3d east = frame.ToLocal(o + Eigen::Vector3d(1000, 0, 0));
  EXPECT_NEAR(east.x(), 1000, 2.0);
  EXPECT_NEAR(east.y(), 0, 5.0);
  EXPECT_NEAR(frame.Info().origin_lon, 9.17, 0.01);
}

TEST(LocalFrame, UndulationMakesHeightsEllipsoidal) {
  const double n = 47.25;
  const LocalFrame ortho("EPSG:25832", kOrigin, n);
  const LocalFrame ellips("EPSG:25832", kOrigin + Eigen::Vector3d(0, 0, n));
  const Eigen::Vector3d p = kOrigin + Eigen::Vector3d(800, -300, 120);
  EXPECT_LT((ortho.ToLocal(p) - ellips.ToLocal(p + Eigen::Vector3d(0, 0, n))).norm(), 1e-6);
  EXPECT_NEAR(ortho.Info().origin_h, kOrigin.z() + n, 1e-6);
  EXPECT_LT((ortho.ToCrs(ortho.ToLocal(p)) - p).norm(), 1e-6);
}

TEST(LocalFrame, UnknownCrsNamesIt) {
  const std::string msg = ErrorOf([] { LocalFrame("EPSG:999999", kOrigin); });
  EXPECT_NE(msg.find("EPSG:999999"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown"), std::string::npos) << msg;
  const std::string garbage = ErrorOf([] { LocalFrame("no such thing", kOrigin); });
  EXPECT_NE(garbage.find("'no such thing'"), std::string::npos) << garbage;
}

TEST(LocalFrame, BallparkVerticalIsRefused) {
  // No GCG2016 grid is installed, so DHHN2016 heights would pass unchanged.
  const std::string msg = ErrorOf([] { LocalFrame("EPSG:25832+7837", kOrigin); });
  EXPECT_NE(msg.find("EPSG:25832+7837"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ballpark"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ellipsoidal"), std::string::npos) << msg;
  EXPECT_NE(msg.find("geoid_undulation"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(LocalFrame, GeocentricAndDoubleGeoidAreRefused) {
  EXPECT_NE(ErrorOf([] { LocalFrame("EPSG:4978", kOrigin); }).find("geocentric"),
            std::string::npos);
  // egm96_15.gtx is installed, so WGS 84 + EGM96 height works without undulation ...
  const Eigen::Vector3d o(500000, 5400000, 100);
  EXPECT_NO_THROW(LocalFrame("EPSG:32632+5773", o));
  // ... and refuses a second geoid on top.
  EXPECT_NE(ErrorOf([&] { LocalFrame("EPSG:32632+5773", o, 47.0); }).find("undulation"),
            std::string::npos);
}

TEST(LocalFrame, GeographicCrsTakesLongitudeFirst) {
  const Eigen::Vector3d o(9.168, 48.7529, 150.0);
  const LocalFrame frame("EPSG:4937", o);  // ETRS89 3D, latitude-first in EPSG
  const GeographicLib::LocalCartesian lc(o.y(), o.x(), o.z(),
                                         GeographicLib::Geocentric(kGrs80A, kGrs80F));
  Eigen::Vector3d want;
  lc.Forward(o.y() + 0.01, o.x() + 0.02, 200.0, want.x(), want.y(), want.z());
  EXPECT_LT((frame.ToLocal({o.x() + 0.02, o.y() + 0.01, 200.0}) - want).norm(), 1e-6);
  EXPECT_NEAR(frame.ConvergenceDeg(o + Eigen::Vector3d(0.02, 0.01, 0)), 0.0, 1e-6);
}

TEST(LocalFrame, WithoutCrsItIsTheIdentity) {
  const LocalFrame frame("", Eigen::Vector3d(10, 20, 30));
  EXPECT_FALSE(frame.HasCrs());
  const Eigen::Vector3d p(123.4, -5.6, 7.8);
  EXPECT_EQ(frame.ToLocal(p), p);
  EXPECT_EQ(frame.ToCrs(p), p);
  EXPECT_EQ(frame.GridToLocal(p), Eigen::Matrix3d::Identity());
  EXPECT_EQ(frame.ConvergenceDeg(p), 0.0);
  EXPECT_FALSE(frame.Info().HasCrs());
}

TEST(LocalFrame, ProjStringFromPrjFile) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(prj, "data/multiview/orthority-ngi-aerial/ngi_xyz_opk.prj");
  std::ifstream in(prj);
  std::stringstream text;
  text << in.rdbuf();
  std::string crs = text.str();
  while (!crs.empty() && std::isspace(static_cast<unsigned char>(crs.back()))) crs.pop_back();
  const Eigen::Vector3d o(-56000, -3729000, 500);
  const LocalFrame frame(crs, o);
  // Lo25: transverse Mercator at 25°E, k = 1, WGS 84, south-oriented
  // northing negative; ~33.7°S.
  EXPECT_NEAR(frame.Info().origin_lon, 25 - 56000 / (111320 * std::cos(33.7 * M_PI / 180)), 0.01);
  EXPECT_NEAR(frame.Info().origin_lat, -33.7, 0.05);
  // West of the central meridian in the southern hemisphere the grid
  // north still leans towards the central meridian: positive convergence.
  EXPECT_GT(frame.ConvergenceDeg(o), 0.2);
  EXPECT_LT(frame.ConvergenceDeg(o), 0.4);
}

TEST(LocalFrame, ConcurrentUseGivesTheSameNumbers) {
  const LocalFrame frame("EPSG:25832", kOrigin);
  std::vector<Eigen::Vector3d> want;
  for (int i = 0; i < 200; ++i)
    want.push_back(frame.ToLocal(kOrigin + Eigen::Vector3d(10.0 * i, -7.0 * i, i)));
  std::vector<int> bad(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int rep = 0; rep < 20; ++rep) {
        for (int i = 0; i < 200; ++i) {
          if (frame.ToLocal(kOrigin + Eigen::Vector3d(10.0 * i, -7.0 * i, i)) !=
              want[static_cast<size_t>(i)])
            ++bad[static_cast<size_t>(t)];
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int b : bad) EXPECT_EQ(b, 0);
}

}  // namespace
}  // namespace roofsweep
