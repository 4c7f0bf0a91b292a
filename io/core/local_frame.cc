#include "io/core/local_frame.h"

#include <ogr_spatialref.h>
#include <proj.h>
#include <proj_experimental.h>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <mutex>
#include <sstream>
#include <vector>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/core/gdal_util.h"

namespace roofsweep {
namespace {

std::string Describe(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.precision(12);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// Owns one PJ and destroys it with the right context.
struct PjHolder {
  PJ_CONTEXT* ctx = nullptr;
  PJ* pj = nullptr;
  PjHolder(PJ_CONTEXT* c, PJ* p) : ctx(c), pj(p) {}
  ~PjHolder() {
    if (pj) proj_destroy(pj);
  }
  PjHolder(const PjHolder&) = delete;
  PjHolder& operator=(const PjHolder&) = delete;
  PJ* release() {
    PJ* p = pj;
    pj = nullptr;
    return p;
  }
};

}  // namespace

struct LocalFrame::Impl {
  std::string crs;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double undulation = 0;
  bool geographic = false;  // positions in degrees
  PJ_CONTEXT* ctx = nullptr;
  PJ* op = nullptr;  // CRS (x, y, h) -> (lon, lat, h) on the CRS's own datum
  GeographicLib::LocalCartesian lc;
  double lat0 = 0, lon0 = 0, h0 = 0;
  std::vector<std::string> proj_log;
  mutable std::mutex mutex;  // PJ objects keep per-call state

  ~Impl() {
    if (op) proj_destroy(op);
    if (ctx) proj_context_destroy(ctx);
  }

  std::string LastProjMessage() const {
    if (!proj_log.empty()) return proj_log.back();
    const int err = proj_context_errno(ctx);
    if (err != 0) return proj_context_errno_string(ctx, err);
    return "no details";
  }

  [[noreturn]] void Fail(const std::string& what) const {
    throw Error("CRS '" + crs + "': " + what);
  }

  PJ* Parse();
  void Build(const Eigen::Vector3d& origin_crs);

  // CRS coordinates to geographic (lon, lat, h ellipsoidal); caller locks.
  Eigen::Vector3d ToGeographic(const Eigen::Vector3d& p) const {
    proj_errno_reset(op);
    PJ_COORD c = proj_coord(p.x(), p.y(), p.z() + undulation, 0);
    PJ_COORD r = proj_trans(op, PJ_FWD, c);
    if (!std::isfinite(r.xyz.x) || !std::isfinite(r.xyz.y) || !std::isfinite(r.xyz.z) ||
        proj_errno(op) != 0) {
      Fail("cannot transform the point " + Describe(p) + " (" +
           proj_context_errno_string(ctx, proj_errno(op)) + ")");
    }
    return {r.xyz.x, r.xyz.y, r.xyz.z};
  }

  Eigen::Vector3d FromGeographic(const Eigen::Vector3d& g) const {
    proj_errno_reset(op);
    PJ_COORD c = proj_coord(g.x(), g.y(), g.z(), 0);
    PJ_COORD r = proj_trans(op, PJ_INV, c);
    if (!std::isfinite(r.xyz.x) || !std::isfinite(r.xyz.y) || !std::isfinite(r.xyz.z) ||
        proj_errno(op) != 0) {
      Fail("cannot transform the geographic point " + Describe(g) + " back (" +
           proj_context_errno_string(ctx, proj_errno(op)) + ")");
    }
    return {r.xyz.x, r.xyz.y, r.xyz.z - undulation};
  }

  Eigen::Vector3d ToLocalLocked(const Eigen::Vector3d& p) const {
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
      j.col(i) = (ToLocalLocked(p + d) - ToLocalLocked(p - d)).normalized();
    }
    return j;
  }
};

PJ* LocalFrame::Impl::Parse() {
  PJ* p = proj_create(ctx, crs.c_str());
  if (p && proj_is_crs(p)) return p;
  if (p) proj_destroy(p);
  // A bare PROJ string describes an operation unless it says +type=crs.
  if (crs.find("+proj=") != std::string::npos && crs.find("+type=crs") == std::string::npos) {
    p = proj_create(ctx, (crs + " +type=crs").c_str());
    if (p && proj_is_crs(p)) return p;
    if (p) proj_destroy(p);
  }
  // GDAL's reader knows a few more spellings (ESRI .prj WKT1, URNs, OGC URLs).
  gdal::ErrorCapture quiet;
  OGRSpatialReference srs;
  if (srs.SetFromUserInput(crs.c_str()) == OGRERR_NONE) {
    char* wkt = nullptr;
    const char* options[] = {"FORMAT=WKT2_2019", nullptr};
    if (srs.exportToWkt(&wkt, options) == OGRERR_NONE && wkt) {
      p = proj_create(ctx, wkt);
      CPLFree(wkt);
      if (p && proj_is_crs(p)) return p;
      if (p) proj_destroy(p);
    } else {
      CPLFree(wkt);
    }
  }
  Fail("unknown or unparsable CRS (PROJ: " + LastProjMessage() + ")");
}

void LocalFrame::Impl::Build(const Eigen::Vector3d& origin_crs) {
  origin = origin_crs;
  PjHolder parsed(ctx, Parse());
  PJ* src_2d = parsed.pj;
  PjHolder base(ctx, nullptr);
  if (proj_get_type(src_2d) == PJ_TYPE_BOUND_CRS) {
    // The +towgs84 of a bound CRS concerns other datums; positions stay on
    // the base CRS's own datum.
    base.pj = proj_get_source_crs(ctx, src_2d);
    src_2d = base.pj;
  }

  const PJ_TYPE type = proj_get_type(src_2d);
  PjHolder src(ctx, nullptr);
  PjHolder horizontal(ctx, nullptr);
  switch (type) {
    case PJ_TYPE_PROJECTED_CRS:
    case PJ_TYPE_GEOGRAPHIC_2D_CRS:
      // Heights become explicitly ellipsoidal instead of passing through.
      src.pj = proj_crs_promote_to_3D(ctx, nullptr, src_2d);
      geographic = type == PJ_TYPE_GEOGRAPHIC_2D_CRS;
      break;
    case PJ_TYPE_GEOGRAPHIC_3D_CRS:
      src.pj = proj_clone(ctx, src_2d);
      geographic = true;
      break;
    case PJ_TYPE_COMPOUND_CRS: {
      if (undulation != 0) {
        Fail(
            "a compound CRS already defines its heights; a geoid undulation cannot be added "
            "(use the horizontal CRS with height_type orthometric, or drop the undulation)");
      }
      horizontal.pj = proj_crs_get_sub_crs(ctx, src_2d, 0);
      const PJ_TYPE h = horizontal.pj ? proj_get_type(horizontal.pj) : PJ_TYPE_UNKNOWN;
      geographic = h == PJ_TYPE_GEOGRAPHIC_2D_CRS || h == PJ_TYPE_GEOGRAPHIC_3D_CRS;
      src.pj = proj_clone(ctx, src_2d);
      break;
    }
    default:
      Fail(std::string("a ") + (type == PJ_TYPE_GEOCENTRIC_CRS ? "geocentric" : "non-projected") +
           " CRS cannot be a block CRS; use a projected CRS with ellipsoidal heights");
  }
  if (!src.pj) Fail("cannot make a 3D CRS of it (PROJ: " + LastProjMessage() + ")");

  PjHolder geodetic(ctx, proj_crs_get_geodetic_crs(ctx, src.pj));
  if (!geodetic.pj || proj_get_type(geodetic.pj) == PJ_TYPE_GEOCENTRIC_CRS) {
    Fail("has no geographic base CRS");
  }
  PjHolder dst(ctx, proj_get_type(geodetic.pj) == PJ_TYPE_GEOGRAPHIC_3D_CRS
                        ? proj_clone(ctx, geodetic.pj)
                        : proj_crs_promote_to_3D(ctx, nullptr, geodetic.pj));
  PjHolder ellipsoid(ctx, proj_get_ellipsoid(ctx, geodetic.pj));
  double a = 0, b = 0, inv_f = 0;
  int inv_f_computed = 0;
  if (!dst.pj || !ellipsoid.pj ||
      !proj_ellipsoid_get_parameters(ctx, ellipsoid.pj, &a, &b, &inv_f_computed, &inv_f)) {
    Fail("cannot read its datum and ellipsoid (PROJ: " + LastProjMessage() + ")");
  }
  const double f = inv_f > 0 ? 1.0 / inv_f : 0.0;

  PJ_OPERATION_FACTORY_CONTEXT* factory = proj_create_operation_factory_context(ctx, nullptr);
  proj_operation_factory_context_set_grid_availability_use(
      ctx, factory, PROJ_GRID_AVAILABILITY_DISCARD_OPERATION_IF_MISSING_GRID);
  proj_operation_factory_context_set_spatial_criterion(ctx, factory,
                                                       PROJ_SPATIAL_CRITERION_PARTIAL_INTERSECTION);
  PJ_OBJ_LIST* ops = proj_create_operations(ctx, src.pj, dst.pj, factory);
  proj_operation_factory_context_destroy(factory);
  PjHolder chosen(ctx, nullptr);
  bool saw_ballpark = false;
  const int count = ops ? proj_list_get_count(ops) : 0;
  for (int i = 0; i < count && !chosen.pj; ++i) {
    PjHolder candidate(ctx, proj_list_get(ctx, ops, i));
    if (!candidate.pj) continue;
    if (proj_coordoperation_has_ballpark_transformation(ctx, candidate.pj)) {
      saw_ballpark = true;
      continue;
    }
    if (!proj_coordoperation_is_instantiable(ctx, candidate.pj)) continue;
    chosen.pj = candidate.release();
  }
  if (ops) proj_list_destroy(ops);
  if (!chosen.pj) {
    if (saw_ballpark) {
      Fail(
          "PROJ can only convert its heights by a ballpark step that leaves them unchanged "
          "(the geoid grid is not installed); give positions with ellipsoidal heights in the "
          "horizontal CRS, or set height_type \"orthometric\" with a constant geoid_undulation");
    }
    Fail("no transformation to its geographic 3D CRS (PROJ: " + LastProjMessage() + ")");
  }
  op = proj_normalize_for_visualization(ctx, chosen.pj);
  if (!op) Fail("cannot normalise the axis order (PROJ: " + LastProjMessage() + ")");

  const Eigen::Vector3d g = ToGeographic(origin_crs);
  lon0 = g.x();
  lat0 = g.y();
  h0 = g.z();
  lc = GeographicLib::LocalCartesian(lat0, lon0, h0, GeographicLib::Geocentric(a, f));
}

LocalFrame::LocalFrame(const std::string& crs, const Eigen::Vector3d& origin, double undulation)
    : impl_(std::make_unique<Impl>()) {
  impl_->crs = crs;
  impl_->origin = origin;
  impl_->undulation = undulation;
  if (!std::isfinite(undulation)) throw Error("geoid undulation is not a finite number");
  if (!origin.allFinite()) throw Error("local frame origin " + Describe(origin) + " is not finite");
  if (crs.empty()) return;
  impl_->ctx = proj_context_create();
  proj_log_func(impl_->ctx, &impl_->proj_log, [](void* data, int level, const char* msg) {
    if (level <= PJ_LOG_ERROR && msg) static_cast<std::vector<std::string>*>(data)->push_back(msg);
  });
  impl_->Build(origin);
}

LocalFrame::~LocalFrame() = default;
LocalFrame::LocalFrame(LocalFrame&&) noexcept = default;
LocalFrame& LocalFrame::operator=(LocalFrame&&) noexcept = default;

bool LocalFrame::HasCrs() const { return impl_ && impl_->op != nullptr; }

const Eigen::Vector3d& LocalFrame::OriginCrs() const { return impl_->origin; }

Eigen::Vector3d LocalFrame::ToLocal(const Eigen::Vector3d& crs_xyz) const {
  if (!HasCrs()) return crs_xyz;
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->ToLocalLocked(crs_xyz);
}

Eigen::Vector3d LocalFrame::ToCrs(const Eigen::Vector3d& local_xyz) const {
  if (!HasCrs()) return local_xyz;
  std::lock_guard<std::mutex> lock(impl_->mutex);
  double lat = 0, lon = 0, h = 0;
  impl_->lc.Reverse(local_xyz.x(), local_xyz.y(), local_xyz.z(), lat, lon, h);
  return impl_->FromGeographic({lon, lat, h});
}

Eigen::Matrix3d LocalFrame::GridToLocal(const Eigen::Vector3d& crs_xyz) const {
  if (!HasCrs()) return Eigen::Matrix3d::Identity();
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return NearestRotation(impl_->NormalisedJacobian(crs_xyz));
}

double LocalFrame::ConvergenceDeg(const Eigen::Vector3d& crs_xyz) const {
  if (!HasCrs()) return 0.0;
  std::lock_guard<std::mutex> lock(impl_->mutex);
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
