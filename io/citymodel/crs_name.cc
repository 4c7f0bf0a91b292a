#include "io/citymodel/crs_name.h"

#include <ogr_spatialref.h>

#include <regex>

namespace roofsweep {

namespace {
std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}
}  // namespace

std::string NormalizeCrsName(const std::string& name) {
  const std::string s = Trim(name);
  std::smatch m;
  static const std::regex urn(R"(^urn:ogc:def:crs:EPSG:[0-9.]*:([0-9]+)$)", std::regex::icase);
  static const std::regex url(R"(^https?://www\.opengis\.net/def/crs/EPSG/[0-9.]+/([0-9]+)$)",
                              std::regex::icase);
  static const std::regex compound(
      R"(^urn:ogc:def:crs,crs:EPSG:[0-9.]*:([0-9]+),crs:EPSG:[0-9.]*:([0-9]+)$)",
      std::regex::icase);
  static const std::regex epsg(R"(^EPSG:([0-9]+)(\+[0-9]+)?$)", std::regex::icase);
  if (std::regex_match(s, m, urn) || std::regex_match(s, m, url)) return "EPSG:" + m[1].str();
  if (std::regex_match(s, m, compound)) return "EPSG:" + m[1].str() + "+" + m[2].str();
  if (std::regex_match(s, m, epsg)) return "EPSG:" + m[1].str() + m[2].str();
  return s;
}

std::string CrsToOgcUrl(const std::string& crs) {
  std::smatch m;
  static const std::regex epsg(R"(^EPSG:([0-9]+)(\+[0-9]+)?$)");
  const std::string n = NormalizeCrsName(crs);
  if (!std::regex_match(n, m, epsg)) return "";
  return "https://www.opengis.net/def/crs/EPSG/0/" + m[1].str();
}

bool CrsIsGeographic(const std::string& crs) {
  if (crs.empty()) return false;
  OGRSpatialReference srs;
  if (srs.SetFromUserInput(NormalizeCrsName(crs).c_str()) != OGRERR_NONE) return false;
  return srs.IsGeographic();
}

}  // namespace roofsweep
