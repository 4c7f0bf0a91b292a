#include "plugin/cli/convert_lib.h"

#include <filesystem>
#include <set>

#include "algorithms/buildings/solid_check.h"
#include "algorithms/core/error.h"
#include "io/citymodel/reproject.h"
#include "io/core/crs_identity.h"

namespace roofsweep {
namespace {

void CollectIds(const Building& b, std::set<std::string>* ids) {
  ids->insert(b.id);
  for (const Building& p : b.parts) CollectIds(p, ids);
}

// `model` with the buildings of the existing `path` before its own.
void PrependExisting(const std::string& path, const std::string& input, CityModel* model,
                     int* before) {
  CityModel existing = ReadCityModel(path);
  if (!SameHorizontalCrs(existing.crs, model->crs))
    throw Error(input + ": its CRS (" + (model->crs.empty() ? "none" : model->crs) +
                ") is not that of " + path + " (" + (existing.crs.empty() ? "none" : existing.crs) +
                "); -append needs one CRS");
  std::set<std::string> ids;
  for (const Building& b : existing.buildings) CollectIds(b, &ids);
  std::set<std::string> mine;
  for (const Building& b : model->buildings) CollectIds(b, &mine);
  for (const std::string& id : mine)
    if (ids.count(id))
      throw Error(input + ": building " + id + " is in " + path +
                  " already (the same tile appended twice?)");
  *before = static_cast<int>(existing.buildings.size());
  for (Building& b : model->buildings) existing.buildings.push_back(std::move(b));
  model->buildings = std::move(existing.buildings);
}

}  // namespace

ConvertSummary RunConvert(const ConvertRequest& request, Progress& progress) {
  ConvertSummary s;
  if (!request.assign_crs.empty() && !request.target_crs.empty())
    throw Error("-a_srs and -t_srs exclude each other: -a_srs assigns a CRS without transforming");
  s.format = ResolveCityModelFormat(request.output, request.write.format);
  ReportOrCancel(progress, 0.0);
  CityModel model = ReadCityModel(request.input, request.input_format);
  std::error_code ec;
  const bool append = request.append && std::filesystem::exists(request.output, ec);
  // A tile without buildings adds nothing to the gathered model.
  if (model.buildings.empty() && !request.allow_empty && !append) {
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
  if (append) {
    PrependExisting(request.output, request.input, &model, &s.appended_to);
    write_options.overwrite = true;
  }
  ReportOrCancel(progress, 0.2);
  s.buildings = static_cast<int>(model.buildings.size());
  SubProgress write(progress, 0.2, 1.0);
  WriteCityModel(model, request.output, write_options, &write);
  return s;
}

}  // namespace roofsweep
