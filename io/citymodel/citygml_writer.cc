#include "io/citymodel/citygml_writer.h"

#include <libxml/xmlwriter.h>

#include <cctype>
#include <cmath>

#include "algorithms/core/error.h"

namespace roofsweep {

namespace {
constexpr const char* kNsCore = "http://www.opengis.net/citygml/2.0";
constexpr const char* kNsBldg = "http://www.opengis.net/citygml/building/2.0";
constexpr const char* kNsGen = "http://www.opengis.net/citygml/generics/2.0";
constexpr const char* kNsGml = "http://www.opengis.net/gml";
constexpr const char* kNsXlink = "http://www.w3.org/1999/xlink";
constexpr const char* kRoofTypeCodeSpace =
    "http://www.sig3d.org/codelists/standard/building/2.0/_AbstractBuilding_roofType.xml";

const xmlChar* X(const char* s) { return reinterpret_cast<const xmlChar*>(s); }

// "..._poly_<digits>": the form of the generated polygon ids.
bool LooksLikePolygonId(const std::string& id) {
  const auto p = id.rfind("_poly_");
  if (p == std::string::npos || p + 6 == id.size()) return false;
  for (size_t i = p + 6; i < id.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(id[i]))) return false;
  return true;
}
}  // namespace

bool IsValidGmlId(const std::string& id) {
  if (id.empty()) return false;
  const unsigned char c0 = static_cast<unsigned char>(id[0]);
  if (!(std::isalpha(c0) || c0 == '_')) return false;
  for (unsigned char c : id)
    if (!(std::isalnum(c) || c == '_' || c == '-' || c == '.')) return false;
  return true;
}

std::string MakeGmlId(const std::string& id) {
  if (id.empty()) return id;
  std::string out = id;
  for (char& c : out) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (!(std::isalnum(u) || c == '_' || c == '-' || c == '.')) c = '_';
  }
  const unsigned char c0 = static_cast<unsigned char>(out[0]);
  if (!(std::isalpha(c0) || c0 == '_')) out = "id_" + out;
  return out;
}

CityGmlWriter::CityGmlWriter(const std::string& path, const CityModelWriteOptions& options)
    : options_(options), file_(path, options.overwrite) {}

CityGmlWriter::~CityGmlWriter() {
  if (writer_) xmlFreeTextWriter(writer_);
}

void CityGmlWriter::Check(int rc, const char* what) {
  if (rc < 0) throw Error(AtLine(file_.path(), 0, std::string("XML write failed at ") + what));
}

bool CityGmlWriter::Taken(const std::string& id) const {
  return ids_.count(std::hash<std::string>{}(id)) > 0;
}

std::string CityGmlWriter::UniqueId(const std::string& wanted, const std::string& fallback) {
  std::string id = MakeGmlId(wanted);
  if (id.empty() || Taken(id) || LooksLikePolygonId(id)) {
    id = fallback;
    for (int k = 2; Taken(id); ++k) id = fallback + "_" + std::to_string(k);
  }
  ids_.insert(std::hash<std::string>{}(id));
  return id;
}

void CityGmlWriter::Begin(const std::string& crs, const Envelope3& envelope) {
  if (writer_) throw Error(AtLine(file_.path(), 0, "CityGmlWriter::Begin called twice"));
  writer_ = xmlNewTextWriterFilename(file_.temp_path().c_str(), 0);
  if (!writer_) throw Error(AtLine(file_.path(), 0, "cannot create file"));
  srs_name_ = crs;
  decimals_ = CoordinateDecimals(crs, options_);
  xmlTextWriterSetIndent(writer_, 1);
  xmlTextWriterSetIndentString(writer_, X(" "));
  Check(xmlTextWriterStartDocument(writer_, nullptr, "UTF-8", nullptr), "document");
  Check(xmlTextWriterStartElementNS(writer_, X("core"), X("CityModel"), X(kNsCore)), "CityModel");
  Check(xmlTextWriterWriteAttributeNS(writer_, X("xmlns"), X("bldg"), nullptr, X(kNsBldg)), "ns");
  Check(xmlTextWriterWriteAttributeNS(writer_, X("xmlns"), X("gen"), nullptr, X(kNsGen)), "ns");
  Check(xmlTextWriterWriteAttributeNS(writer_, X("xmlns"), X("gml"), nullptr, X(kNsGml)), "ns");
  Check(xmlTextWriterWriteAttributeNS(writer_, X("xmlns"), X("xlink"), nullptr, X(kNsXlink)), "ns");

  const bool finite = envelope.allFinite();
  xmlTextWriterStartElement(writer_, X("gml:boundedBy"));
  xmlTextWriterStartElement(writer_, X("gml:Envelope"));
  if (!srs_name_.empty()) xmlTextWriterWriteAttribute(writer_, X("srsName"), X(srs_name_.c_str()));
  xmlTextWriterWriteAttribute(writer_, X("srsDimension"), X("3"));
  for (int corner = 0; corner < 2; ++corner) {
    std::string s;
    for (int k = 0; k < 3; ++k) {
      if (k) s += ' ';
      AppendNumber(&s, finite ? envelope[3 * corner + k] : 0.0, decimals_);
    }
    Check(xmlTextWriterWriteElement(writer_, X(corner ? "gml:upperCorner" : "gml:lowerCorner"),
                                    X(s.c_str())),
          "Envelope");
  }
  xmlTextWriterEndElement(writer_);  // Envelope
  Check(xmlTextWriterEndElement(writer_), "boundedBy");
}

void CityGmlWriter::Write(const Building& b) {
  if (!writer_) throw Error(AtLine(file_.path(), 0, "CityGmlWriter::Write before Begin"));
  xmlTextWriterStartElement(writer_, X("core:cityObjectMember"));
  WriteObject(b, "bldg:Building", "BLDG_" + std::to_string(++buildings_));
  // One return code per building catches a full disk without checking every call.
  Check(xmlTextWriterEndElement(writer_), "cityObjectMember");
}

void CityGmlWriter::WriteObject(const Building& b, const char* element,
                                const std::string& fallback_id) {
  const std::string bid = UniqueId(b.id, fallback_id);
  xmlTextWriterStartElement(writer_, X(element));
  xmlTextWriterWriteAttribute(writer_, X("gml:id"), X(bid.c_str()));

  // gen:* come before roofType in the XSD's sequence (core's generic
  // application properties precede the building's own).
  for (const auto& [name, value] : b.double_attributes) {
    std::string v;
    AppendNumber(&v, value, 6);
    xmlTextWriterStartElement(writer_, X("gen:doubleAttribute"));
    xmlTextWriterWriteAttribute(writer_, X("name"), X(name.c_str()));
    xmlTextWriterWriteElement(writer_, X("gen:value"), X(v.c_str()));
    xmlTextWriterEndElement(writer_);
  }
  for (const auto& [name, value] : StringAttributesToWrite(b, options_)) {
    xmlTextWriterStartElement(writer_, X("gen:stringAttribute"));
    xmlTextWriterWriteAttribute(writer_, X("name"), X(name.c_str()));
    xmlTextWriterWriteElement(writer_, X("gen:value"), X(value.c_str()));
    xmlTextWriterEndElement(writer_);
  }
  if (b.roof_type != roof_type::kUnknown) {
    xmlTextWriterStartElement(writer_, X("bldg:roofType"));
    xmlTextWriterWriteAttribute(writer_, X("codeSpace"), X(kRoofTypeCodeSpace));
    xmlTextWriterWriteString(writer_, X(std::to_string(b.roof_type).c_str()));
    xmlTextWriterEndElement(writer_);
  }
  if (b.measured_height > 0 && std::isfinite(b.measured_height)) {
    std::string v;
    AppendNumber(&v, b.measured_height, 3);
    xmlTextWriterStartElement(writer_, X("bldg:measuredHeight"));
    xmlTextWriterWriteAttribute(writer_, X("uom"), X("m"));
    xmlTextWriterWriteString(writer_, X(v.c_str()));
    xmlTextWriterEndElement(writer_);
  }

  size_t polygons = 0;
  for (const Surface& s : b.surfaces) polygons += s.polygons.size();
  int poly_counter = 0;
  if (polygons > 0 && b.lod == 1) {
    // LoD1 has no thematic surfaces in CityGML 2.0 (_BoundarySurface
    // carries lod2-4 geometry only): the block is one solid of its
    // polygons, written inline, and its surfaces take no gml:id.
    StartSolid("bldg:lod1Solid");
    for (size_t si = 0; si < b.surfaces.size(); ++si)
      for (const Polygon3& p : b.surfaces[si].polygons)
        WriteSurfaceMember(p, bid + "_poly_" + std::to_string(poly_counter++),
                           "building " + bid + " surface " + std::to_string(si + 1));
    EndSolid();
  } else if (polygons > 0) {
    // Ids are decided first because the solid references polygons that
    // are written later, under boundedBy.
    std::vector<std::string> surface_ids(b.surfaces.size());
    std::vector<std::vector<std::string>> polygon_ids(b.surfaces.size());
    for (size_t si = 0; si < b.surfaces.size(); ++si) {
      surface_ids[si] = UniqueId(b.surfaces[si].id, bid + "_surf_" + std::to_string(si));
      for (size_t pi = 0; pi < b.surfaces[si].polygons.size(); ++pi)
        polygon_ids[si].push_back(bid + "_poly_" + std::to_string(poly_counter++));
    }
    StartSolid("bldg:lod2Solid");
    for (const auto& ids : polygon_ids)
      for (const auto& pid : ids) {
        xmlTextWriterStartElement(writer_, X("gml:surfaceMember"));
        xmlTextWriterWriteAttribute(writer_, X("xlink:href"), X(("#" + pid).c_str()));
        xmlTextWriterEndElement(writer_);
      }
    EndSolid();

    for (size_t si = 0; si < b.surfaces.size(); ++si) {
      const Surface& s = b.surfaces[si];
      const std::string type = std::string("bldg:") + SurfaceTypeName(s.type);
      xmlTextWriterStartElement(writer_, X("bldg:boundedBy"));
      xmlTextWriterStartElement(writer_, X(type.c_str()));
      xmlTextWriterWriteAttribute(writer_, X("gml:id"), X(surface_ids[si].c_str()));
      xmlTextWriterStartElement(writer_, X("bldg:lod2MultiSurface"));
      xmlTextWriterStartElement(writer_, X("gml:MultiSurface"));
      for (size_t pi = 0; pi < s.polygons.size(); ++pi)
        WriteSurfaceMember(s.polygons[pi], polygon_ids[si][pi],
                           "building " + bid + " surface " + surface_ids[si]);
      xmlTextWriterEndElement(writer_);  // MultiSurface
      xmlTextWriterEndElement(writer_);  // lod2MultiSurface
      xmlTextWriterEndElement(writer_);  // *Surface
      xmlTextWriterEndElement(writer_);  // boundedBy
    }
  }
  // The XSD's sequence puts the parts after boundedBy (and before address).
  for (size_t k = 0; k < b.parts.size(); ++k) {
    xmlTextWriterStartElement(writer_, X("bldg:consistsOfBuildingPart"));
    WriteObject(b.parts[k], "bldg:BuildingPart", bid + "_part_" + std::to_string(k + 1));
    xmlTextWriterEndElement(writer_);
  }
  xmlTextWriterEndElement(writer_);  // Building or BuildingPart
}

void CityGmlWriter::StartSolid(const char* property) {
  xmlTextWriterStartElement(writer_, X(property));
  xmlTextWriterStartElement(writer_, X("gml:Solid"));
  xmlTextWriterStartElement(writer_, X("gml:exterior"));
  xmlTextWriterStartElement(writer_, X("gml:CompositeSurface"));
}

void CityGmlWriter::EndSolid() {
  for (int k = 0; k < 4; ++k) xmlTextWriterEndElement(writer_);
}

void CityGmlWriter::WriteSurfaceMember(const Polygon3& p, const std::string& id,
                                       const std::string& context) {
  xmlTextWriterStartElement(writer_, X("gml:surfaceMember"));
  xmlTextWriterStartElement(writer_, X("gml:Polygon"));
  xmlTextWriterWriteAttribute(writer_, X("gml:id"), X(id.c_str()));
  for (size_t r = 0; r <= p.holes.size(); ++r) {
    const auto& ring = r == 0 ? p.exterior : p.holes[r - 1];
    if (ring.empty()) throw Error(AtLine(file_.path(), 0, context + ": empty ring"));
    buffer_.clear();
    for (size_t k = 0; k <= ring.size(); ++k) {  // repeats the first point
      const Eigen::Vector3d& v = ring[k % ring.size()];
      for (int c = 0; c < 3; ++c) {
        if (!buffer_.empty()) buffer_ += ' ';
        AppendNumber(&buffer_, v[c], decimals_);
      }
    }
    xmlTextWriterStartElement(writer_, X(r == 0 ? "gml:exterior" : "gml:interior"));
    xmlTextWriterStartElement(writer_, X("gml:LinearRing"));
    xmlTextWriterStartElement(writer_, X("gml:posList"));
    xmlTextWriterWriteAttribute(writer_, X("srsDimension"), X("3"));
    xmlTextWriterWriteString(writer_, X(buffer_.c_str()));
    xmlTextWriterEndElement(writer_);
    xmlTextWriterEndElement(writer_);
    xmlTextWriterEndElement(writer_);
  }
  xmlTextWriterEndElement(writer_);  // Polygon
  xmlTextWriterEndElement(writer_);  // surfaceMember
}

void CityGmlWriter::End() {
  if (!writer_) throw Error(AtLine(file_.path(), 0, "CityGmlWriter::End before Begin"));
  Check(xmlTextWriterEndDocument(writer_), "end of document");
  Check(xmlTextWriterFlush(writer_), "flush");
  xmlFreeTextWriter(writer_);
  writer_ = nullptr;
  file_.Commit();
}

}  // namespace roofsweep
