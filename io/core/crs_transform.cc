#include "io/core/crs_transform.h"

#include <ogr_spatialref.h>
#include <proj.h>
#include <proj_experimental.h>

#include <cmath>
#include <mutex>
#include <sstream>
#include <vector>

#include "algorithms/core/error.h"
#include "io/core/gdal_util.h"

namespace roofsweep {
namespace {

std::string Describe(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.precision(12);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// Owns one PJ and destroys it (PJ objects remember their context).
struct PjHolder {
  PJ* pj = nullptr;
  explicit PjHolder(PJ* p = nullptr) : pj(p) {}
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

CrsKind KindOfType(PJ_TYPE t) {
  switch (t) {
    case PJ_TYPE_PROJECTED_CRS:
      return CrsKind::kProjected;
    case PJ_TYPE_GEOGRAPHIC_2D_CRS:
      return CrsKind::kGeographic2D;
    case PJ_TYPE_GEOGRAPHIC_3D_CRS:
      return CrsKind::kGeographic3D;
    case PJ_TYPE_COMPOUND_CRS:
      return CrsKind::kCompound;
    case PJ_TYPE_GEOCENTRIC_CRS:
      return CrsKind::kGeocentric;
    default:
      return CrsKind::kOther;
  }
}

}  // namespace

struct CrsTransform::Impl {
  PJ_CONTEXT* ctx = nullptr;
  PJ* op = nullptr;    // source -> target, axes normalised for visualisation
  std::string prefix;  // "CRS 'x': " or "'x' -> 'y': " for messages
  CrsKind source_kind = CrsKind::kOther;
  CrsKind target_kind = CrsKind::kOther;
  double a = 0, f = 0;
  std::vector<std::string> proj_log;
  mutable std::mutex mutex;  // PJ objects keep per-call state

  Impl() {
    ctx = proj_context_create();
    proj_log_func(ctx, &proj_log, [](void* data, int level, const char* msg) {
      if (level <= PJ_LOG_ERROR && msg)
        static_cast<std::vector<std::string>*>(data)->push_back(msg);
    });
  }
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

  [[noreturn]] void Fail(const std::string& what) const { throw Error(prefix + what); }

  // The CRS named by `crs`, a bound CRS replaced by its base: its +towgs84
  // concerns other datums, positions stay on the base CRS's own datum.
  PJ* Parse(const std::string& crs, const std::string& prefix_for_errors);
  // A 3D version: 2D projected/geographic promoted (ellipsoidal heights).
  PJ* Make3D(PJ* crs, const std::string& prefix_for_errors);
  void ReadEllipsoid(PJ* crs);
  void Select(PJ* src, PJ* dst, const CrsTransformOptions& options, const std::string& target);

  Eigen::Vector3d Apply(const Eigen::Vector3d& p, PJ_DIRECTION dir) const {
    std::lock_guard<std::mutex> lock(mutex);
    proj_errno_reset(op);
    PJ_COORD r = proj_trans(op, dir, proj_coord(p.x(), p.y(), p.z(), 0));
    if (!std::isfinite(r.xyz.x) || !std::isfinite(r.xyz.y) || !std::isfinite(r.xyz.z) ||
        proj_errno(op) != 0) {
      Fail("cannot transform the point " + Describe(p) + (dir == PJ_INV ? " back" : "") + " (" +
           proj_context_errno_string(ctx, proj_errno(op)) + ")");
    }
    return {r.xyz.x, r.xyz.y, r.xyz.z};
  }
};

PJ* CrsTransform::Impl::Parse(const std::string& crs, const std::string& pfx) {
  auto unwrap = [&](PJ* p) {
    if (proj_get_type(p) != PJ_TYPE_BOUND_CRS) return p;
    PJ* base = proj_get_source_crs(ctx, p);
    proj_destroy(p);
    return base;
  };
  PJ* p = proj_create(ctx, crs.c_str());
  if (p && proj_is_crs(p)) return unwrap(p);
  if (p) proj_destroy(p);
  // A bare PROJ string describes an operation unless it says +type=crs.
  if (crs.find("+proj=") != std::string::npos && crs.find("+type=crs") == std::string::npos) {
    p = proj_create(ctx, (crs + " +type=crs").c_str());
    if (p && proj_is_crs(p)) return unwrap(p);
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
      if (p && proj_is_crs(p)) return unwrap(p);
      if (p) proj_destroy(p);
    } else {
      CPLFree(wkt);
    }
  }
  throw Error(pfx + "unknown or unparsable CRS (PROJ: " + LastProjMessage() + ")");
}

PJ* CrsTransform::Impl::Make3D(PJ* crs, const std::string& pfx) {
  const PJ_TYPE t = proj_get_type(crs);
  PJ* out = t == PJ_TYPE_PROJECTED_CRS || t == PJ_TYPE_GEOGRAPHIC_2D_CRS
                ? proj_crs_promote_to_3D(ctx, nullptr, crs)
                : proj_clone(ctx, crs);
  if (!out) throw Error(pfx + "cannot make a 3D CRS of it (PROJ: " + LastProjMessage() + ")");
  return out;
}

void CrsTransform::Impl::ReadEllipsoid(PJ* crs) {
  PjHolder ellipsoid(proj_get_ellipsoid(ctx, crs));
  double b = 0, inv_f = 0;
  int inv_f_computed = 0;
  if (!ellipsoid.pj ||
      !proj_ellipsoid_get_parameters(ctx, ellipsoid.pj, &a, &b, &inv_f_computed, &inv_f)) {
    Fail("cannot read its datum and ellipsoid (PROJ: " + LastProjMessage() + ")");
  }
  f = inv_f > 0 ? 1.0 / inv_f : 0.0;
}

void CrsTransform::Impl::Select(PJ* src, PJ* dst, const CrsTransformOptions& options,
                                const std::string& target) {
  PJ_OPERATION_FACTORY_CONTEXT* factory = proj_create_operation_factory_context(ctx, nullptr);
  proj_operation_factory_context_set_grid_availability_use(
      ctx, factory, PROJ_GRID_AVAILABILITY_DISCARD_OPERATION_IF_MISSING_GRID);
  proj_operation_factory_context_set_spatial_criterion(ctx, factory,
                                                       PROJ_SPATIAL_CRITERION_PARTIAL_INTERSECTION);
  if (options.area_of_interest) {
    const Eigen::Vector4d& b = *options.area_of_interest;
    proj_operation_factory_context_set_area_of_interest(ctx, factory, b[0], b[1], b[2], b[3]);
  }
  PJ_OBJ_LIST* ops = proj_create_operations(ctx, src, dst, factory);
  proj_operation_factory_context_destroy(factory);
  PjHolder chosen;
  bool saw_ballpark = false;
  const int count = ops ? proj_list_get_count(ops) : 0;
  // PROJ sorts the candidates by relevance (area, accuracy); the first one
  // without a ballpark step that can run here wins.
  for (int i = 0; i < count && !chosen.pj; ++i) {
    PjHolder candidate(proj_list_get(ctx, ops, i));
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
      const bool heights = source_kind == CrsKind::kCompound || target_kind == CrsKind::kCompound;
      Fail(heights ? "PROJ can only convert its heights by a ballpark step that leaves them "
                     "unchanged (the geoid grid is not installed); " +
                         options.ballpark_hint
                   : "PROJ knows only a ballpark transformation to " + target +
                         " (a datum shift of unknown accuracy, metres); " + options.ballpark_hint);
    }
    Fail("no transformation to " + target + " (PROJ: " + LastProjMessage() + ")");
  }
  op = proj_normalize_for_visualization(ctx, chosen.pj);
  if (!op) Fail("cannot normalise the axis order (PROJ: " + LastProjMessage() + ")");
}

CrsTransform::CrsTransform() : impl_(std::make_unique<Impl>()) {}

CrsTransform::CrsTransform(const std::string& source, const std::string& target,
                           const CrsTransformOptions& options)
    : CrsTransform() {
  Impl& m = *impl_;
  if (source.empty()) throw Error("no source CRS to transform from");
  if (target.empty()) throw Error("no target CRS to transform to");
  m.prefix = "CRS '" + source + "' -> '" + target + "': ";
  PjHolder src2(m.Parse(source, "CRS '" + source + "': "));
  PjHolder dst2(m.Parse(target, "CRS '" + target + "': "));
  m.source_kind = KindOfType(proj_get_type(src2.pj));
  m.target_kind = KindOfType(proj_get_type(dst2.pj));
  PjHolder src(m.Make3D(src2.pj, "CRS '" + source + "': "));
  PjHolder dst(m.Make3D(dst2.pj, "CRS '" + target + "': "));
  m.ReadEllipsoid(src.pj);
  m.Select(src.pj, dst.pj, options, "'" + target + "'");
}

CrsTransform CrsTransform::ToOwnGeographic3D(const std::string& crs,
                                             const CrsTransformOptions& options) {
  CrsTransform t;
  Impl& m = *t.impl_;
  m.prefix = "CRS '" + crs + "': ";
  PjHolder parsed(m.Parse(crs, m.prefix));
  m.source_kind = KindOfType(proj_get_type(parsed.pj));
  PjHolder src(m.Make3D(parsed.pj, m.prefix));
  PjHolder geodetic(proj_crs_get_geodetic_crs(m.ctx, src.pj));
  if (!geodetic.pj || proj_get_type(geodetic.pj) == PJ_TYPE_GEOCENTRIC_CRS) {
    m.Fail("has no geographic base CRS");
  }
  PjHolder dst(proj_get_type(geodetic.pj) == PJ_TYPE_GEOGRAPHIC_3D_CRS
                   ? proj_clone(m.ctx, geodetic.pj)
                   : proj_crs_promote_to_3D(m.ctx, nullptr, geodetic.pj));
  if (!dst.pj) m.Fail("cannot read its datum and ellipsoid (PROJ: " + m.LastProjMessage() + ")");
  m.target_kind = CrsKind::kGeographic3D;
  m.ReadEllipsoid(geodetic.pj);
  m.Select(src.pj, dst.pj, options, "its geographic 3D CRS");
  return t;
}

CrsKind CrsTransform::KindOf(const std::string& crs, CrsKind* horizontal) {
  Impl m;
  PjHolder parsed(m.Parse(crs, "CRS '" + crs + "': "));
  const CrsKind kind = KindOfType(proj_get_type(parsed.pj));
  if (horizontal) {
    *horizontal = kind;
    if (kind == CrsKind::kCompound) {
      PjHolder h(proj_crs_get_sub_crs(m.ctx, parsed.pj, 0));
      *horizontal = h.pj ? KindOfType(proj_get_type(h.pj)) : CrsKind::kOther;
    }
  }
  return kind;
}

CrsTransform::~CrsTransform() = default;
CrsTransform::CrsTransform(CrsTransform&&) noexcept = default;
CrsTransform& CrsTransform::operator=(CrsTransform&&) noexcept = default;

Eigen::Vector3d CrsTransform::Forward(const Eigen::Vector3d& p) const {
  return impl_->Apply(p, PJ_FWD);
}

Eigen::Vector3d CrsTransform::Inverse(const Eigen::Vector3d& p) const {
  return impl_->Apply(p, PJ_INV);
}

CrsKind CrsTransform::source_kind() const { return impl_->source_kind; }
CrsKind CrsTransform::target_kind() const { return impl_->target_kind; }
double CrsTransform::source_semi_major() const { return impl_->a; }
double CrsTransform::source_flattening() const { return impl_->f; }

std::string CrsTransform::operation_name() const {
  const char* n = proj_get_name(impl_->op);
  return n ? n : "";
}

}  // namespace roofsweep
