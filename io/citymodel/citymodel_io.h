#pragma once

#include <memory>
#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "io/citymodel/citymodel_writer.h"

namespace roofsweep {

class Progress;

// The format-neutral front that `roofsweep convert IN OUT [-of FMT]` calls.
//
// Format names (case-insensitive): "CityGML", "CityJSON", "CityJSONSeq", or
// any GDAL vector driver that can create files ("GPKG", "FlatGeobuf",
// "GeoJSON", ...). From the extension: .gml/.xml CityGML, .json/.city.json
// CityJSON, .jsonl/.city.jsonl CityJSONSeq, .gpkg GPKG, .fgb FlatGeobuf,
// .geojson GeoJSON, .sqlite SQLite.

struct WriteOptions : CityModelWriteOptions {
  std::string format;  // empty: from the output's extension
  // roofsweep's own writers: "NAME=VALUE" creation options (-co). CityGML
  // knows DECIMALS=N (0-17, CityModelWriteOptions::decimals); CityJSON and
  // CityJSONSeq have none (their precision is the transform's scale: 1 mm,
  // 1e-8 degrees). Refused for OGR formats, which take
  // dataset_options/layer_options instead.
  std::vector<std::string> creation_options;
};

// The canonical format name for `format` (or, when empty, for `path`'s
// extension): "CityGML", "CityJSON", "CityJSONSeq" or the GDAL driver name.
// Throws roofsweep::Error when neither names a known format.
std::string ResolveCityModelFormat(const std::string& path, const std::string& format = {});

// Reads any of the formats above (`format` empty: by extension, and for
// unknown extensions by content sniffing: XML, JSON, or GDAL).
CityModel ReadCityModel(const std::string& path, const std::string& format = {});

// Writes `model` with a streaming writer (memory bounded for CityGML,
// CityJSONSeq and OGR formats). Atomic: the file appears complete or not at
// all. `progress` (optional) is updated per building and may cancel.
void WriteCityModel(const CityModel& model, const std::string& path,
                    const WriteOptions& options = {}, Progress* progress = nullptr);

// A streaming writer for `path` in the resolved format, for callers that
// produce buildings one at a time (Begin/Write/End).
std::unique_ptr<CityModelStreamWriter> OpenCityModelWriter(const std::string& path,
                                                           const WriteOptions& options = {});

}  // namespace roofsweep
