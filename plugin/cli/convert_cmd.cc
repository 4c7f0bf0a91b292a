#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/convert_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Convert(const std::vector<std::string>& args, Context& ctx) {
  ConvertRequest r;
  bool no_check = false;
  ArgParser p("convert",
              "Converts a LoD2 model between CityGML 2.0, CityJSON 2.0, CityJSONSeq, "
              "GeoPackage and other OGR vector formats.");
  p.Positional("IN", &r.input, "input model (.gml CityGML 1.0/2.0, .city.json, .city.jsonl, .gpkg)")
      .Positional("OUT", &r.output, "output model; the format follows the extension unless -of")
      .Option("-of|-f", &r.write.format, "FORMAT",
              "CityGML, CityJSON, CityJSONSeq, or a GDAL vector driver (GPKG, FlatGeobuf, GeoJSON)")
      .Option("-if", &r.input_format, "FORMAT", "input format, when the extension does not tell")
      .Option("-a_srs", &r.assign_crs, "SRS", "CRS to assign to the output (no reprojection)")
      .Option("-t_srs", &r.target_crs, "SRS",
              "reproject the output to this CRS through PROJ (EPSG:code, WKT, PROJ string); "
              "a 2D CRS keeps ellipsoidal heights, ballpark height steps are refused")
      .KeyValues("-co", &r.write.creation_options,
                 "creation option of roofsweep's writers: CityGML DECIMALS=N (decimals per "
                 "coordinate; default 4, 9 for degrees); CityJSON has none")
      .KeyValues("-dsco", &r.write.dataset_options,
                 "GDAL dataset creation option for OGR outputs (e.g. GPKG VERSION=1.2)")
      .KeyValues("-lco", &r.write.layer_options,
                 "GDAL layer creation option for OGR outputs, every layer (e.g. GPKG "
                 "SPATIAL_INDEX=NO, FID=fid, GEOMETRY_NAME=geom)")
      .Flag("-overwrite", &r.write.overwrite, "replace an existing output file")
      .Flag("-update", &r.write.update,
            "GeoPackage: add or replace roofsweep's layers in an existing file, keep the others")
      .Flag("-append", &r.append,
            "add the input's buildings to those of an existing OUT (same CRS, no id in both): "
            "gathers the outputs of a tiled run; without OUT a plain write")
      .Flag("-allow_empty", &r.allow_empty, "write a model that has no buildings")
      .Flag("-no_check", &no_check, "do not run the solid checks (roofsweep_validity attribute)")
      .Example("roofsweep convert buildings.gml buildings.city.json")
      .Example("roofsweep convert buildings.city.json city.gpkg -update")
      .Example("roofsweep convert buildings.gml buildings_wgs84.city.json -t_srs EPSG:4979")
      .Example("for t in tiles/*.gml; do roofsweep convert $t city.gml -append; done");
  if (!p.Parse(args)) return 0;
  if (!r.assign_crs.empty() && !r.target_crs.empty())
    throw UsageError("Options -a_srs and -t_srs exclude each other", p.Synopsis());
  RequireCityModelFormat(p, r.output, r.write.format);
  if (r.append && (r.write.overwrite || r.write.update))
    throw UsageError("Option -append excludes -overwrite and -update", p.Synopsis());
  RequireNewOutput(p, r.output, r.write.overwrite || r.write.update || r.append);
  r.write.check_geometry = !no_check;
  const ConvertSummary s = RunConvert(r, *ctx.progress);
  if (!ctx.quiet) {
    std::cout << "Wrote " << r.output << " (" << s.format << "): " << s.buildings << " buildings";
    if (s.appended_to)
      std::cout << " (" << s.appended_to << " there before, " << s.buildings - s.appended_to
                << " added with " << s.surfaces << " surfaces)";
    else
      std::cout << ", " << s.surfaces << " surfaces";
    if (s.invalid_buildings)
      std::cout << ", " << s.invalid_buildings << " failing the solid checks";
    std::cout << "\n";
  }
  return 0;
}

const CommandRegistration kRegistration{
    {"convert", "convert LoD2 models between CityGML, CityJSON and GeoPackage", Convert}};

}  // namespace
}  // namespace roofsweep::cli
