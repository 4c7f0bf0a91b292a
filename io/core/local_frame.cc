#include "io/core/local_frame.h"

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/core/crs_transform.h"

namespace roofsweep {
namespace {

std::string Describe(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.precision(12);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

}  // namespace

struct LocalFrame::Impl {
  std::string crs;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double undulation = 0;
  bool geographic = false;  // positions in degrees
  // CRS (x, y, h) -> (lon, lat, h) on the CRS's own datum; empty without a CRS.
  std::optional<CrsTransform> to_geographic;
  GeographicLib::LocalCartesian lc;
  double lat0 = 0, lon0 = 0, h0 = 0;

  [[noreturn]] void Fail(const std::string& what) const {
    throw Error("CRS '" + crs + "': " + what);
  }

  void Build(const Eigen::Vector3d& origin_crs);

  // CRS coordinates to geographic (lon, lat, h ellipsoidal).
  Eigen::Vector3d ToGeographic(const Eigen::Vector3d& p) const {
    return to_geographic->Forward(p + Eigen::Vector3d(0, 0, undulation));
  }

  Eigen::Vector3d FromGeographic(const Eigen::Vector3d& g) const {
    return to_geographic->Inverse(g) - Eigen::Vector3d(0, 0, undulation);
  }

  Eigen::Vector3d ToLocalGeo(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d g = ToGeographic(p);
    Eigen::Vector3d out;
    lc.Forward(g.y(), g.x(), g.z(), out.x(), out.y(), out.z());
    return out;
  }

  // Columns: d(local)/d(crs axis), each normalised. Central differences
  // work for every projection PROJ knows, not only transverse Mercator;
  // their truncation error (step² / R²) is 1e-12 for 10 m steps, and long
  // steps keep PROJ's nanometre-level series noise out of the angles.
  Eigen::Matrix3d NormalisedJacobian(const Eigen::Vector3d& p) const {
    const double step_h = geographic ? 1e-4 : 10.0;
    const double steps[3] = {step_h, step_h, 10.0};
    Eigen::Matrix3d j;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      d[i] = steps[i];
      j.col(i) = (ToLocalGeo(p + d) - ToLocalGeo(p - d)).normalized();
    }
    return j;
  }
};

void LocalFrame::Impl::Build(const Eigen::Vector3d& origin_crs) {
  origin = origin_crs;
  CrsKind horizontal = CrsKind::kOther;
  switch (CrsTransform::KindOf(crs, &horizontal)) {
    case CrsKind::kProjected:
    case CrsKind::kGeographic2D:
    case CrsKind::kGeographic3D:
      geographic = horizontal != CrsKind::kProjected;
      break;
    case CrsKind::kCompound:
      if (undulation != 0) {
        Fail(
            "a compound CRS already defines its heights; a geoid undulation cannot be added "
            "(use the horizontal CRS with height_type orthometric, or drop the undulation)");
      }
      geographic = horizontal == CrsKind::kGeographic2D || horizontal == CrsKind::kGeographic3D;
      break;
    case CrsKind::kGeocentric:
    case CrsKind::kOther:
      Fail(std::string("a ") +
           (horizontal == CrsKind::kGeocentric ? "geocentric" : "non-projected") +
           " CRS cannot be a block CRS; use a projected CRS with ellipsoidal heights");
  }
  CrsTransformOptions options;
  options.ballpark_hint =
      "give positions with ellipsoidal heights in the horizontal CRS, or set height_type "
      "\"orthometric\" with a constant geoid_undulation";
  to_geographic = CrsTransform::ToOwnGeographic3D(crs, options);
  const Eigen::Vector3d g = ToGeographic(origin_crs);
  lon0 = g.x();
  lat0 = g.y();
  h0 = g.z();
  lc = GeographicLib::LocalCartesian(lat0, lon0, h0,
                                     GeographicLib::Geocentric(to_geographic->source_semi_major(),
                                                               to_geographic->source_flattening()));
}

LocalFrame::LocalFrame(const std::string& crs, const Eigen::Vector3d& origin, double undulation)
    : impl_(std::make_unique<Impl>()) {
  impl_->crs = crs;
  impl_->origin = origin;
  impl_->undulation = undulation;
  if (!std::isfinite(undulation)) throw Error("geoid undulation is not a finite number");
  if (!origin.allFinite()) throw Error("local frame origin " + Describe(origin) + " is not finite");
  if (crs.empty()) return;
  impl_->Build(origin);
}

LocalFrame::~LocalFrame() = default;
LocalFrame::LocalFrame(LocalFrame&&) noexcept = default;
LocalFrame& LocalFrame::operator=(LocalFrame&&) noexcept = default;

bool LocalFrame::HasCrs() const { return impl_ && impl_->to_geographic.has_value(); }

const Eigen::Vector3d& LocalFrame::OriginCrs() const { return impl_->origin; }

Eigen::Vector3d LocalFrame::ToLocal(const Eigen::Vector3d& crs_xyz) const {
  if (!HasCrs()) return crs_xyz;
  return impl_->ToLocalGeo(crs_xyz);
}

Eigen::Vector3d LocalFrame::ToCrs(const Eigen::Vector3d& local_xyz) const {
  if (!HasCrs()) return local_xyz;
  double lat = 0, lon = 0, h = 0;
  impl_->lc.Reverse(local_xyz.x(), local_xyz.y(), local_xyz.z(), lat, lon, h);
  return impl_->FromGeographic({lon, lat, h});
}

Eigen::Matrix3d LocalFrame::GridToLocal(const Eigen::Vector3d& crs_xyz) const {
  if (!HasCrs()) return Eigen::Matrix3d::Identity();
  return NearestRotation(impl_->NormalisedJacobian(crs_xyz));
}

double LocalFrame::ConvergenceDeg(const Eigen::Vector3d& crs_xyz) const {
  if (!HasCrs()) return 0.0;
  const Eigen::Matrix3d j = impl_->NormalisedJacobian(crs_xyz);
  // Grid north expressed in the ENU axes at the point itself, so that the
  // angle is the projection's convergence, not the frame's meridian offset.
  const Eigen::Vector3d g = impl_->ToGeographic(crs_xyz);
  double x, y, z;
  std::vector<double> m(9);
  impl_->lc.Forward(g.y(), g.x(), g.z(), x, y, z, m);
  const Eigen::Matrix3d enu_p_to_local =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m.data());
  const Eigen::Vector3d north = enu_p_to_local.transpose() * j.col(1);
  return std::atan2(north.x(), north.y()) * 180.0 / M_PI;
}

FrameInfo LocalFrame::Info() const {
  FrameInfo info;
  if (!HasCrs()) return info;
  info.crs = impl_->crs;
  info.origin_lat = impl_->lat0;
  info.origin_lon = impl_->lon0;
  info.origin_h = impl_->h0;
  return info;
}

}  // namespace roofsweep
