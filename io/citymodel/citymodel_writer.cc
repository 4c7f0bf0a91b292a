#include "io/citymodel/citymodel_writer.h"

#include <cmath>
#include <cstdio>

#include "io/citymodel/crs_name.h"

namespace roofsweep {

std::map<std::string, std::string> StringAttributesToWrite(const Building& b,
                                                           const CityModelWriteOptions& options) {
  std::map<std::string, std::string> out = b.string_attributes;
  // A building made of parts has no solid of its own; each part says.
  if (options.check_geometry && !(b.surfaces.empty() && !b.parts.empty()))
    out[kValidityAttribute] = CheckBuildingSolid(b, options.check).Summary();
  return out;
}

int CoordinateDecimals(const std::string& crs, const CityModelWriteOptions& options) {
  if (options.decimals >= 0) return options.decimals;
  return CrsIsGeographic(crs) ? 9 : 4;
}

void AppendNumber(std::string* out, double v, int decimals) {
  char buf[64];
  int n = std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  if (decimals > 0) {
    while (n > 0 && buf[n - 1] == '0') --n;
    if (n > 0 && buf[n - 1] == '.') --n;
  }
  if (n == 2 && buf[0] == '-' && buf[1] == '0') n = 1, buf[0] = '0';  // "-0" -> "0"
  out->append(buf, static_cast<size_t>(n));
}

}  // namespace roofsweep
