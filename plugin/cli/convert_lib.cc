#include "plugin/cli/convert_lib.h"

#include "algorithms/buildings/solid_check.h"
#include "algorithms/core/error.h"
#include "io/citymodel/reproject.h"

namespace roofsweep {

ConvertSummary RunConvert(const ConvertRequest& request, Progress& progress) {
  ConvertSummary s;
  if (!request.assign_crs.empty() && !request.target_crs.empty())
    throw Error("-a_srs and -t_srs exclude each other: -a_srs assigns a CRS without transforming");
  s.format = ResolveCityModelFormat(request.output, request.write.format);
  ReportOrCancel(progress, 0.0);
  CityModel model = ReadCityModel(request.input, request.input_format);
  if (model.buildings.empty() && !request.allow_empty) {
    throw Error(request.input + ": no buildings found (nothing to convert)");
  }
  if (!request.assign_crs.empty()) model.crs = request.assign_crs;
  WriteOptions write_options = request.write;
  // The solid checks' tolerances are metres: run them before a reprojection
  // (to degrees, perhaps) and write their outcome as it was.
  // Each part is a solid of its own; a building is invalid when one is.
  for (Building& building : model.buildings) {
    bool valid = true;
    for (Building* b : building.Solids()) {
      s.surfaces += static_cast<int>(b->surfaces.size());
      const SolidCheckResult check = CheckBuildingSolid(*b, request.write.check);
      valid = valid && check.Valid();
      if (!request.target_crs.empty() && request.write.check_geometry)
        b->string_attributes[kValidityAttribute] = check.Summary();
    }
    if (!valid) ++s.invalid_buildings;
  }
  if (!request.target_crs.empty()) {
    if (model.crs.empty())
      throw Error(request.input + ": the model has no CRS to reproject from (-t_srs)");
    ReprojectCityModel(model, request.target_crs);
    write_options.check_geometry = false;
  }
  ReportOrCancel(progress, 0.2);
  s.buildings = static_cast<int>(model.buildings.size());
  SubProgress write(progress, 0.2, 1.0);
  WriteCityModel(model, request.output, write_options, &write);
  return s;
}

}  // namespace roofsweep
