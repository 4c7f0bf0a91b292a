#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/buildings/solid_check.h"

namespace roofsweep {

// Options shared by every CityModel writer.
struct CityModelWriteOptions {
  // Replace an existing output file. Without it (and without `update`) an
  // existing output is an error: no format silently replaces a file.
  bool overwrite = false;
  // GeoPackage only: open the existing file and add or replace roofsweep's
  // layers, keeping the others. The file is copied, changed and renamed back,
  // so a failure leaves the original untouched.
  bool update = false;
  // Run CheckBuildingSolid on each building and write the outcome as the
  // string attribute `roofsweep_validity` ("valid" or the val3dity codes).
  bool check_geometry = true;
  SolidCheckOptions check;
  // Decimals for written coordinates; -1 chooses 4 (0.1 mm) for projected or
  // local metres and 9 for geographic degrees.
  int decimals = -1;
  // OGR formats only (GPKG, FlatGeobuf, ...): GDAL dataset and layer
  // creation options as "NAME=VALUE" (ogr2ogr's -dsco and -lco), checked
  // against the driver's lists: an unknown name or a bad value is an error.
  // Layer options apply to every layer and override roofsweep's own
  // (GPKG: SPATIAL_INDEX=YES, GEOMETRY_NAME=geom). The CityGML and CityJSON
  // writers refuse them.
  std::vector<std::string> dataset_options;
  std::vector<std::string> layer_options;
};

// Name of the validity attribute the writers add.
inline constexpr const char* kValidityAttribute = "roofsweep_validity";

// (min x, min y, min z, max x, max y, max z), as CityModel::Bounds().
using Envelope3 = Eigen::Matrix<double, 6, 1>;

// A writer that takes one building at a time, so large models stream to disk
// without the whole document in memory. Call Begin once, Write per building,
// then End, which completes the file and renames it into place; destroying a
// writer without End removes the temporary file.
class CityModelStreamWriter {
 public:
  virtual ~CityModelStreamWriter() = default;
  // `envelope` is written first by formats that want it up front (CityGML);
  // compute it with CityModel::Bounds().
  virtual void Begin(const std::string& crs, const Envelope3& envelope) = 0;
  virtual void Write(const Building& building) = 0;
  virtual void End() = 0;
};

// String attributes to write for `b`: its own plus roofsweep_validity when
// options.check_geometry (which replaces a stale one read from a file).
std::map<std::string, std::string> StringAttributesToWrite(const Building& b,
                                                           const CityModelWriteOptions& options);

// Decimals to print for `crs` under `options` (see CityModelWriteOptions).
int CoordinateDecimals(const std::string& crs, const CityModelWriteOptions& options);

// Prints `v` with `decimals` decimals and without trailing zeros ("106",
// "500000.1234"), the shortest text that keeps the chosen precision.
void AppendNumber(std::string* out, double v, int decimals);

}  // namespace roofsweep
