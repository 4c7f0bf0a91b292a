#include "plugin/cli/convert_lib.h"

#include "algorithms/buildings/solid_check.h"
#include "algorithms/core/error.h"

namespace roofsweep {

ConvertSummary RunConvert(const ConvertRequest& request, Progress& progress) {
  ConvertSummary s;
  s.format = ResolveCityModelFormat(request.output, request.write.format);
  ReportOrCancel(progress, 0.0);
  CityModel model = ReadCityModel(request.input, request.input_format);
  if (model.buildings.empty() && !request.allow_empty) {
    throw Error(request.input + ": no buildings found (nothing to convert)");
  }
  if (!request.assign_crs.empty()) model.crs = request.assign_crs;
  ReportOrCancel(progress, 0.2);
  for (const Building& b : model.buildings) {
    s.surfaces += static_cast<int>(b.surfaces.size());
    if (!CheckBuildingSolid(b, request.write.check).Valid()) ++s.invalid_buildings;
  }
  s.buildings = static_cast<int>(model.buildings.size());
  SubProgress write(progress, 0.2, 1.0);
  WriteCityModel(model, request.output, request.write, &write);
  return s;
}

}  // namespace roofsweep
