#include "io/citymodel/reproject.h"

#include <algorithm>

#include "algorithms/core/error.h"
#include "io/citymodel/crs_name.h"
#include "io/core/crs_transform.h"

namespace roofsweep {
namespace {

// The model's longitude/latitude box, so that PROJ picks an operation valid
// where the buildings are (several exist for many datum pairs); none when
// the corners cannot be transformed.
std::optional<Eigen::Vector4d> GeographicExtent(const CityModel& model, const std::string& crs) {
  if (model.buildings.empty()) return std::nullopt;
  const Eigen::Matrix<double, 6, 1> b = model.Bounds();
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
  options.area_of_interest = GeographicExtent(model, source);
  const CrsTransform t(source, NormalizeCrsName(target_srs), options);
  CityModel out = model;  // unchanged on failure
  out.TransformVertices([&](const Eigen::Vector3d& v) { return t.Forward(v); });
  out.crs = target_srs;
  model = std::move(out);
}

}  // namespace roofsweep
