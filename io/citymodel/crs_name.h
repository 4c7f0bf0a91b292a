#pragma once

#include <string>

namespace roofsweep {

// CRS names as the formats spell them. CityGML files use "EPSG:25833",
// "urn:ogc:def:crs:EPSG::25833" or the compound URN; CityJSON uses the OGC
// URL. roofsweep's CityModel::crs keeps the short form "EPSG:25833" (or
// "EPSG:25832+7837"), so these functions translate at the file boundary.

// "urn:ogc:def:crs:EPSG::25833", "urn:ogc:def:crs:EPSG:6.12:25833",
// "http(s)://www.opengis.net/def/crs/EPSG/0/25833" -> "EPSG:25833";
// "urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837" -> "EPSG:25832+7837";
// anything else is returned unchanged (trimmed).
std::string NormalizeCrsName(const std::string& name);

// "https://www.opengis.net/def/crs/EPSG/0/25833" for an EPSG code (the
// compound form has no single URL: only its horizontal code is used, as
// CityJSON wants one URL); empty when `crs` is not an EPSG code.
std::string CrsToOgcUrl(const std::string& crs);

// True when the CRS is geographic (degrees), judged by PROJ through OSR; used
// to pick the number of decimals written.
bool CrsIsGeographic(const std::string& crs);

}  // namespace roofsweep
