#include "io/citymodel/citymodel_io.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>

#include "algorithms/core/error.h"
#include "algorithms/core/progress.h"
#include "io/citymodel/citygml_reader.h"
#include "io/citymodel/citygml_writer.h"
#include "io/citymodel/cityjson_reader.h"
#include "io/citymodel/cityjson_writer.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/output_file.h"

namespace roofsweep {

namespace {

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string FormatFromExtension(const std::string& path) {
  const std::string p = Lower(path);
  if (EndsWith(p, ".gml") || EndsWith(p, ".xml")) return "CityGML";
  if (EndsWith(p, ".jsonl")) return "CityJSONSeq";
  if (EndsWith(p, ".json")) return "CityJSON";
  return OgrDriverForPath(path);
}

// First non-blank bytes decide between XML and JSON; the rest goes to GDAL.
std::string SniffFormat(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  const auto i = head.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (i == std::string::npos) return "";
  if (head[i] == '<') return "CityGML";
  if (head[i] == '{') {
    const auto nl = head.find('\n', i);
    const bool seq =
        nl != std::string::npos && head.find("CityJSONFeature", nl) != std::string::npos;
    return seq ? "CityJSONSeq" : "CityJSON";
  }
  return "OGR";
}

// -co for roofsweep's own writers; -dsco/-lco belong to OGR formats.
CityModelWriteOptions ApplyCreationOptions(const std::string& path, const std::string& format,
                                           bool ogr, const WriteOptions& options) {
  CityModelWriteOptions o = options;
  if (ogr) {
    if (!options.creation_options.empty())
      throw Error(AtLine(path, 0,
                         "creation options (-co) apply to CityGML/CityJSON outputs; for " + format +
                             " use dataset (-dsco) or layer (-lco) creation options"));
    return o;
  }
  if (!options.dataset_options.empty() || !options.layer_options.empty())
    throw Error(AtLine(path, 0,
                       "dataset/layer creation options (-dsco/-lco) apply to GDAL formats, not " +
                           format + " (roofsweep's own writers take -co)"));
  for (const std::string& c : options.creation_options) {
    const auto eq = c.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(AtLine(path, 0, "creation option '" + c + "' is not NAME=VALUE"));
    const std::string name = Lower(c.substr(0, eq)), value = c.substr(eq + 1);
    if (name != "decimals" || format != "CityGML")
      throw Error(AtLine(
          path, 0,
          format + " has no creation option '" + c.substr(0, eq) + "' (" +
              (format == "CityGML" ? "known: DECIMALS" : "its precision is the transform's scale") +
              ")"));
    char* end = nullptr;
    const long d = std::strtol(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || d < 0 || d > 17)
      throw Error(AtLine(path, 0, "creation option DECIMALS expects 0 to 17, got '" + value + "'"));
    o.decimals = static_cast<int>(d);
  }
  return o;
}

}  // namespace

std::string ResolveCityModelFormat(const std::string& path, const std::string& format) {
  if (format.empty()) {
    const std::string f = FormatFromExtension(path);
    if (f.empty())
      throw Error(AtLine(path, 0,
                         "cannot tell the format from the extension; name one (-of "
                         "CityGML|CityJSON|CityJSONSeq|GPKG|FlatGeobuf|...)"));
    return f;
  }
  const std::string l = Lower(format);
  if (l == "citygml" || l == "gml") return "CityGML";
  if (l == "cityjson" || l == "json") return "CityJSON";
  if (l == "cityjsonseq" || l == "jsonl" || l == "cityjsonl") return "CityJSONSeq";
  if (IsOgrVectorWriteDriver(format)) return format;
  throw Error(AtLine(path, 0, "unknown output format '" + format + "'"));
}

CityModel ReadCityModel(const std::string& path, const std::string& format) {
  CheckInputFile(path);
  std::string f = format.empty() ? FormatFromExtension(path) : ResolveCityModelFormat(path, format);
  if (f.empty()) f = SniffFormat(path);
  if (f == "CityGML") return ReadCityGml(path);
  if (f == "CityJSON") return ReadCityJson(path);
  if (f == "CityJSONSeq") return ReadCityJsonSeq(path);
  return ReadOgrCityModel(path);
}

std::unique_ptr<CityModelStreamWriter> OpenCityModelWriter(const std::string& path,
                                                           const WriteOptions& options) {
  const std::string f = ResolveCityModelFormat(path, options.format);
  const bool ogr = f != "CityGML" && f != "CityJSON" && f != "CityJSONSeq";
  if (options.update && !ogr)
    throw Error(AtLine(path, 0, "update applies to GeoPackage outputs only; use overwrite"));
  const CityModelWriteOptions o = ApplyCreationOptions(path, f, ogr, options);
  if (f == "CityGML") return std::make_unique<CityGmlWriter>(path, o);
  if (f == "CityJSON") return std::make_unique<CityJsonWriter>(path, o);
  if (f == "CityJSONSeq") return std::make_unique<CityJsonSeqWriter>(path, o);
  return std::make_unique<OgrCityModelWriter>(path, f, o);
}

void WriteCityModel(const CityModel& model, const std::string& path, const WriteOptions& options,
                    Progress* progress) {
  auto writer = OpenCityModelWriter(path, options);
  if (auto* ogr = dynamic_cast<OgrCityModelWriter*>(writer.get())) {
    std::map<std::string, bool> attrs;  // FlatGeobuf needs the schema up front
    for (const auto& building : model.buildings) {
      std::vector<const Building*> objects = building.Solids();
      objects.push_back(&building);
      for (const Building* b : objects) {
        for (const auto& kv : b->double_attributes) attrs.emplace(kv.first, true);
        for (const auto& kv : b->string_attributes) attrs.emplace(kv.first, false);
      }
    }
    ogr->DeclareAttributes(attrs);
  }
  writer->Begin(model.crs, model.Bounds());
  const size_t n = model.buildings.size();
  for (size_t i = 0; i < n; ++i) {
    writer->Write(model.buildings[i]);
    if (progress && (i % 64 == 0 || i + 1 == n))
      ReportOrCancel(*progress, static_cast<double>(i + 1) / static_cast<double>(n), "writing");
  }
  writer->End();
}

}  // namespace roofsweep
