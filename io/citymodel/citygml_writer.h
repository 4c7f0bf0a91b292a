#pragma once

#include <memory>
#include <string>
#include <unordered_set>

#include "io/citymodel/citymodel_writer.h"
#include "io/citymodel/output_file.h"

typedef struct _xmlTextWriter* xmlTextWriterPtr;

namespace roofsweep {

// Streams CityGML 2.0 LoD2 through libxml2's xmlTextWriter (libcitygml has no
// writer and GDAL's GML driver cannot produce CityGML; see
// docs/ecosystem-notes §2). Each building becomes a bldg:Building with
// gen:* attributes, roofType (SIG3D codeSpace), measuredHeight, a lod2Solid
// whose surfaceMembers reference the thematic surfaces' polygons by xlink,
// and bldg:boundedBy Roof/Wall/Ground/ClosureSurface; its parts follow as
// bldg:consistsOfBuildingPart/bldg:BuildingPart, each written the same way.
// Output validates against CityGML-2.0-all.xsd.
class CityGmlWriter final : public CityModelStreamWriter {
 public:
  // Throws roofsweep::Error for a missing folder or an existing output
  // without options.overwrite.
  CityGmlWriter(const std::string& path, const CityModelWriteOptions& options = {});
  ~CityGmlWriter() override;

  void Begin(const std::string& crs, const Envelope3& envelope) override;
  void Write(const Building& building) override;
  void End() override;

 private:
  // A Building or BuildingPart (`element`) with its parts.
  void WriteObject(const Building& b, const char* element, const std::string& fallback_id);
  // One gml:surfaceMember holding the polygon (with its gml:id);
  // `context` names the building and surface in the error on an empty ring.
  void WriteSurfaceMember(const Polygon3& p, const std::string& id, const std::string& context);
  // `property` (bldg:lod1Solid, bldg:lod2Solid) down to the
  // gml:CompositeSurface whose members the caller writes; EndSolid closes
  // the four.
  void StartSolid(const char* property);
  void EndSolid();
  std::string UniqueId(const std::string& wanted, const std::string& fallback);
  bool Taken(const std::string& id) const;
  void Check(int rc, const char* what);

  CityModelWriteOptions options_;
  OutputFile file_;
  xmlTextWriterPtr writer_ = nullptr;
  std::string srs_name_;
  int decimals_ = 4;
  // Hashes of the building and surface gml:ids written so far (xs:ID must be
  // unique in the document): the only state that grows with the building
  // count, one hash per building and surface. Polygon ids are not kept: they
  // are "<building id>_poly_<k>" and a surface id of that form is replaced,
  // so they cannot collide. A hash collision only renames an id.
  std::unordered_set<size_t> ids_;
  size_t buildings_ = 0;
  std::string buffer_;
};

// True when `id` is an NCName that may serve as gml:id (starts with a letter
// or '_', then letters, digits, '.', '-', '_'; ASCII only here).
bool IsValidGmlId(const std::string& id);
// `id` made valid: invalid characters become '_', and "id_" is prefixed when
// it does not start with a letter or '_'. Empty stays empty.
std::string MakeGmlId(const std::string& id);

}  // namespace roofsweep
