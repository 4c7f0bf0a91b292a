#include "io/core/crs_identity.h"

#include "io/core/gdal_util.h"

namespace roofsweep {

namespace {

std::string AuthorityName(const OGRSpatialReference& srs) {
  const char* auth = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  return auth && code && *auth && *code ? std::string(auth) + ":" + code : "";
}

}  // namespace

std::unique_ptr<OGRSpatialReference> HorizontalCrs(const OGRSpatialReference& srs) {
  auto h = std::make_unique<OGRSpatialReference>(srs);
  if (h->IsCompound()) {
    h->StripVertical();
  } else if (h->GetAxesCount() > 2) {
    h->DemoteTo2D(nullptr);
  }
  h->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return h;
}

std::string IdentifyCrs(const OGRSpatialReference& srs) {
  if (std::string n = AuthorityName(srs); !n.empty()) return n;
  const auto h = HorizontalCrs(srs);
  if (std::string n = AuthorityName(*h); !n.empty()) return n;
  // Confidence 100 only: a CRS that merely resembles an EPSG one must not
  // take its code.
  OGRSpatialReference* match = h->FindBestMatch(100);
  if (!match) return "";
  std::string n = AuthorityName(*match);
  match->Release();
  return n;
}

bool SameHorizontalCrs(const std::string& a, const std::string& b) {
  if (a == b) return true;
  OGRSpatialReference sa, sb;
  gdal::ErrorCapture quiet;
  if (sa.SetFromUserInput(a.c_str()) != OGRERR_NONE ||
      sb.SetFromUserInput(b.c_str()) != OGRERR_NONE)
    return false;
  const char* options[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES", nullptr};
  return HorizontalCrs(sa)->IsSame(HorizontalCrs(sb).get(), options);
}

}  // namespace roofsweep
