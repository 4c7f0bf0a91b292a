#include "io/citymodel/reproject.h"

#include <algorithm>
#include <limits>

#include "algorithms/core/error.h"
#include "io/citymodel/crs_name.h"
#include "io/core/crs_transform.h"

namespace roofsweep {
namespace {

// The longitude/latitude box of the bounds (min x, y, z, max x, y, z), so
// that PROJ picks an operation valid where the data are (several exist for
// many datum pairs); none when the corners cannot be transformed.
std::optional<Eigen::Vector4d> GeographicExtent(const Eigen::Matrix<double, 6, 1>& b,
                                                const std::string& crs) {
  try {
    const CrsTransform to_geo = CrsTransform::ToOwnGeographic3D(crs);
    Eigen::Vector4d box(1e9, 1e9, -1e9, -1e9);
    for (double x : {b[0], b[3]})
      for (double y : {b[1], b[4]}) {
        const Eigen::Vector3d g = to_geo.Forward({x, y, b[2]});
        box = Eigen::Vector4d(std::min(box[0], g.x()), std::min(box[1], g.y()),
                              std::max(box[2], g.x()), std::max(box[3], g.y()));
      }
    return box;
  } catch (const Error&) {
    return std::nullopt;  // the transformation itself reports the real problem
  }
}

}  // namespace

void ReprojectCityModel(CityModel& model, const std::string& target_srs) {
  if (model.crs.empty())
    throw Error("the model has no CRS to reproject from (assign one with -a_srs)");
  const std::string source = NormalizeCrsName(model.crs);
  CrsTransformOptions options;
  if (!model.buildings.empty()) options.area_of_interest = GeographicExtent(model.Bounds(), source);
  const CrsTransform t(source, NormalizeCrsName(target_srs), options);
  CityModel out = model;  // unchanged on failure
  out.TransformVertices([&](const Eigen::Vector3d& v) { return t.Forward(v); });
  out.crs = target_srs;
  model = std::move(out);
}

void ReprojectSegments(SegmentSet& set, const std::string& target_srs) {
  if (set.crs.empty()) throw Error("the lines have no CRS to reproject from");
  const std::string source = NormalizeCrsName(set.crs);
  CrsTransformOptions options;
  if (!set.segments.empty()) {
    Eigen::Matrix<double, 6, 1> b;
    b.head<3>().setConstant(std::numeric_limits<double>::infinity());
    b.tail<3>().setConstant(-std::numeric_limits<double>::infinity());
    for (const LabelledSegment& s : set.segments)
      for (const Eigen::Vector3d& p : {s.segment.a, s.segment.b}) {
        b.head<3>() = b.head<3>().cwiseMin(p);
        b.tail<3>() = b.tail<3>().cwiseMax(p);
      }
    options.area_of_interest = GeographicExtent(b, source);
  }
  const CrsTransform t(source, NormalizeCrsName(target_srs), options);
  SegmentSet out = set;  // unchanged on failure
  for (LabelledSegment& s : out.segments) {
    s.segment.a = t.Forward(s.segment.a);
    s.segment.b = t.Forward(s.segment.b);
  }
  out.crs = target_srs;
  set = std::move(out);
}

}  // namespace roofsweep
