#include "plugin/cli/usage_checks.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "algorithms/core/error.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/ogr_citymodel.h"

namespace roofsweep::cli {

void RequireNewOutput(const ArgParser& p, const std::string& path, bool replace) {
  std::error_code ec;
  if (!replace && !path.empty() && std::filesystem::exists(path, ec))
    throw UsageError("Output " + path + " exists; pass -overwrite to replace it", p.Synopsis());
}

void RequireVectorFormat(const ArgParser& p, const std::string& path, const std::string& format) {
  if (format.empty()) {
    if (!path.empty() && OgrDriverForPath(path).empty())
      throw UsageError("Cannot tell the vector format of " + path +
                           " from its extension; name it with -of (GPKG, FlatGeobuf, ...)",
                       p.Synopsis());
    return;
  }
  if (!IsOgrVectorWriteDriver(format))
    throw UsageError("Unknown output format '" + format +
                         "' (-of takes a GDAL vector driver that can create files: GPKG, "
                         "FlatGeobuf, GeoJSON, ...; see --formats)",
                     p.Synopsis());
}

void RequireCityModelFormat(const ArgParser& p, const std::string& path,
                            const std::string& format) {
  try {
    ResolveCityModelFormat(path, format);
  } catch (const Error& e) {
    // ResolveCityModelFormat names the file; usage errors name the option.
    throw UsageError(format.empty()
                         ? "Cannot tell the format of " + path +
                               " from its extension; name it with -of (CityGML, CityJSON, "
                               "CityJSONSeq, GPKG, FlatGeobuf, ...)"
                         : "Unknown output format '" + format +
                               "' (-of takes CityGML, CityJSON, CityJSONSeq or a GDAL vector "
                               "driver that can create files; see --formats)",
                     p.Synopsis());
  }
}

Eigen::Vector4d ParseAoi(const ArgParser& p, const std::string& text) {
  double a, b, c, d;
  char tail;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf%c", &a, &b, &c, &d, &tail) != 4 ||
      !std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d) || a >= c ||
      b >= d)
    throw UsageError("Option -aoi expects MINX,MINY,MAXX,MAXY, got '" + text + "'", p.Synopsis());
  return Eigen::Vector4d(a, b, c, d);
}

std::optional<Eigen::Vector4d> ParseTileOptions(const ArgParser& p, const std::string& aoi,
                                                double tile_buffer_m) {
  if (!(tile_buffer_m >= 0))
    throw UsageError("Option -tile_buffer expects a distance of 0 m or more", p.Synopsis());
  if (aoi.empty()) return std::nullopt;
  return ParseAoi(p, aoi);
}

}  // namespace roofsweep::cli
