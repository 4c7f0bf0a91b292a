#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "plugin/cli/arg_parser.h"

namespace roofsweep::cli {

// Wrong usage the parser cannot see by itself: checked right after
// ArgParser::Parse, before any work, and thrown as UsageError so the program
// prints the one-line error plus the command's usage and exits 1, like an
// unknown option.

// `path` exists and the command may not replace it (`replace` false).
void RequireNewOutput(const ArgParser& p, const std::string& path, bool replace);

// -of for a GDAL vector output: `format` names a driver that can create
// files, or is empty and `path`'s extension tells one.
void RequireVectorFormat(const ArgParser& p, const std::string& path, const std::string& format);

// -of for a city model output (CityGML, CityJSON, CityJSONSeq or a GDAL
// vector driver), or the extension of `path` when `format` is empty.
void RequireCityModelFormat(const ArgParser& p, const std::string& path, const std::string& format);

// -aoi MINX,MINY,MAXX,MAXY: four finite numbers with min < max.
Eigen::Vector4d ParseAoi(const ArgParser& p, const std::string& text);

// The tile options of run, sweep and match: -aoi (`aoi` empty: none given)
// and -tile_buffer, a distance of 0 m or more.
std::optional<Eigen::Vector4d> ParseTileOptions(const ArgParser& p, const std::string& aoi,
                                                double tile_buffer_m);

}  // namespace roofsweep::cli
