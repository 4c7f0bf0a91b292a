#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/citymodel/citymodel_writer.h"
#include "io/citymodel/output_file.h"

class GDALDataset;
class OGRLayer;
class OGRSpatialReference;

namespace roofsweep {

// CityModel as OGR simple features, for QGIS and GIS tools.
//
// Multi-layer formats (GPKG, SQLite) get four layers, all MultiPolygonZ in
// the block CRS promoted to 3D (OSRPromoteTo3D: ellipsoidal heights unless
// the CRS is compound), with a spatial index:
//   buildings        footprint = the ground surfaces (of all its parts);
//                    id, roof_type, roof_type_name, measured_height,
//                    lod (2; 1 for a block model, Building::lod),
//                    roofsweep_validity and one field per generic attribute
//   building_parts   (only when a building has parts) the same per part,
//                    with building_id
//   roof_surfaces, wall_surfaces, ground_surfaces (+ closure_surfaces when
//   present)         one feature per semantic surface: building_id,
//                    building_part_id (empty for the building's own),
//                    surface_id, surface_type, surface_index
// Single-layer formats (FlatGeobuf, GeoJSON, ...) get one layer `surfaces`
// holding every semantic surface with the attributes of the building, or of
// the part, it bounds repeated (a building made of parts keeps only its id).
// ReadOgrCityModel rebuilds the CityModel from either layout.
class OgrCityModelWriter final : public CityModelStreamWriter {
 public:
  // `driver` is a GDAL vector driver short name ("GPKG", "FlatGeobuf",
  // "GeoJSON"). Throws for an unknown driver or one that cannot create
  // files, a missing folder, or an existing file without overwrite/update.
  OgrCityModelWriter(const std::string& path, const std::string& driver,
                     const CityModelWriteOptions& options = {});
  ~OgrCityModelWriter() override;

  // Generic attributes expected (name -> true for double, false for string).
  // Formats that fix their schema before the first feature (FlatGeobuf) need
  // every name here; others also accept new names as buildings arrive.
  void DeclareAttributes(const std::map<std::string, bool>& attributes);

  void Begin(const std::string& crs, const Envelope3& envelope) override;
  void Write(const Building& building) override;
  void End() override;

 private:
  struct Layer;
  // A layer with the fields of a building (id, roof type, height,
  // validity, the declared attributes), of a surface (building_id,
  // building_part_id, surface_id, ...) or both; part_fields adds
  // building_id to a building layer (building_parts).
  Layer& MakeLayer(const std::string& name, bool building_fields, bool surface_fields,
                   bool part_fields = false);
  void EnsureField(Layer& layer, const std::string& name, bool is_double);
  void MaybeCommitBatch();

  std::string driver_name_;
  CityModelWriteOptions options_;
  OutputFile file_;
  GDALDataset* ds_ = nullptr;
  bool multi_layer_ = true;
  bool in_transaction_ = false;
  int pending_ = 0;
  size_t written_ = 0;
  std::map<std::string, bool> declared_;
  std::map<std::string, std::unique_ptr<Layer>> layers_;
  std::unique_ptr<OGRSpatialReference> srs_;
};

// Reads a CityModel written by OgrCityModelWriter (either layout). Throws
// roofsweep::Error naming the file when it cannot be opened or has none of
// the expected layers.
CityModel ReadOgrCityModel(const std::string& path);

// The GDAL driver short name for an output path's extension ("GPKG" for
// .gpkg, "FlatGeobuf" for .fgb, "GeoJSON" for .geojson), or empty.
std::string OgrDriverForPath(const std::string& path);
// True when `name` is a GDAL vector driver that can create files.
bool IsOgrVectorWriteDriver(const std::string& name);
// Throws roofsweep::Error naming `path` unless every "NAME=VALUE" of
// `options` is a dataset (`layer` false) or layer creation option that the
// GDAL driver `driver` lists, with a value of the listed type.
void CheckOgrCreationOptions(const std::string& path, const std::string& driver,
                             const std::vector<std::string>& options, bool layer);

// ---- Extra layers (lines3d, half planes, ...) ------------------------------

// kLineString is 2D (x, y of lines[0]; image pixel layers have no z).
enum class LayerGeometry {
  kNone,
  kLineStringZ,
  kMultiLineStringZ,
  kMultiPolygonZ,
  kLineString,
  kPointZ
};

// One feature for WriteFeatureLayer: geometry by kind, attributes by type.
struct LayerFeature {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // PointZ
  std::vector<std::vector<Eigen::Vector3d>> lines;  // LineStringZ uses lines[0]
  std::vector<Polygon3> polygons;
  std::map<std::string, long long> integers;
  std::map<std::string, double> reals;
  std::map<std::string, std::string> strings;
};

struct FeatureLayerOptions {
  std::string driver;  // empty: from the extension
  std::string crs;     // promoted to 3D like the city model layers; empty: none
  // As CityModelWriteOptions: overwrite replaces the whole file, update adds
  // or replaces this layer in an existing file (copy, change, rename).
  bool overwrite = false;
  bool update = false;
  // Layer description (GPKG gpkg_contents.description, DESCRIPTION metadata
  // elsewhere); empty: none.
  std::string description;
  // GDAL dataset and layer creation options, "NAME=VALUE", as in
  // CityModelWriteOptions (checked against the driver's lists; layer options
  // override roofsweep's own and apply to every layer). Dataset options
  // are refused with `update` (the file exists already).
  std::vector<std::string> dataset_options;
  std::vector<std::string> layer_options;
};

// Writes `features` as layer `layer` (fields are the union of the features'
// attribute names). Atomic like the city model writers.
void WriteFeatureLayer(const std::string& path, const std::string& layer, LayerGeometry geometry,
                       const std::vector<LayerFeature>& features,
                       const FeatureLayerOptions& options);

// Several layers in one atomic write (one copy of the file, not one per
// layer). Each layer's description overrides options.description.
struct FeatureLayerData {
  std::string name;
  LayerGeometry geometry = LayerGeometry::kNone;
  std::string description;
  std::vector<LayerFeature> features;
};
void WriteFeatureLayers(const std::string& path, const std::vector<FeatureLayerData>& layers,
                        const FeatureLayerOptions& options);

// The checks WriteFeatureLayers makes before writing (format known and able
// to create files, creation options valid, folder present, no existing file
// without overwrite/update), for commands to fail before their work.
void CheckFeatureLayerOutput(const std::string& path, const FeatureLayerOptions& options);

}  // namespace roofsweep
