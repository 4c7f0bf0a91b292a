#include "plugin/cli/info_lib.h"

#include <cstdio>
#include <sstream>

#include "algorithms/core/format.h"
#include "algorithms/geometry/rotation.h"
#include "io/core/local_frame.h"
#include "io/orientation/block_source.h"
#include "plugin/cli/tile_lib.h"

namespace roofsweep {

BlockInfo RunInfo(const std::string& block) {
  BlockInfo info;
  info.manifest = OpenBlockManifest(block);
  info.block = ManifestToBlock(info.manifest);
  info.overview = AnalyzeBlock(info.block);
  return info;
}

namespace {

std::string Fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

int OverlapCount(const BlockOverview& o, int i) {
  int n = 0;
  for (const auto& e : o.overlaps) n += (e.a == i || e.b == i);
  return n;
}

}  // namespace

std::string FormatInfoText(const BlockInfo& info) {
  const BlockManifest& m = info.manifest;
  const BlockOverview& o = info.overview;
  std::ostringstream s;
  s << "Block: " << m.source << "\n";
  if (m.crs.empty()) {
    s << "CRS: none (local frame; outputs carry no CRS)\n";
  } else {
    s << "CRS: " << (m.crs.size() > 60 ? m.crs.substr(0, 57) + "..." : m.crs) << "\n";
    const FrameInfo& f = info.block.frame;
    s << "Local ENU origin: lat " << Fmt("%.7f", f.origin_lat) << ", lon "
      << Fmt("%.7f", f.origin_lon) << ", h " << Fmt("%.2f", f.origin_h) << " m\n";
  }
  s << "Ground: ";
  if (m.ground_height)
    s << "height " << *m.ground_height << "\n";
  else if (!m.dtm.empty())
    s << "DTM " << m.dtm << "\n";
  else if (!m.dsm.empty())
    s << "terrain from the surface model " << m.dsm << " (opening over " << m.terrain_window_m
      << " m)\n";
  else
    s << "unknown (footprints on the scene plane through the optical axes)\n";
  s << "Cameras: " << m.cameras.size() << "\n";
  for (const Camera& c : m.cameras) {
    s << "  " << c.id << "  " << c.width << "x" << c.height << "  f " << Fmt("%.2f", c.fx) << " px"
      << "  pp (" << Fmt("%.2f", c.cx) << ", " << Fmt("%.2f", c.cy) << ")"
      << (c.HasDistortion() ? "  Brown distortion" : "") << "\n";
  }
  s << "Images: " << m.images.size() << "\n";
  s << "  name                      camera        X             Y             Z      omega    phi"
       "      kappa   GSD[m]  above[m] off-nadir overlaps\n";
  for (size_t i = 0; i < m.images.size(); ++i) {
    const ManifestImage& im = m.images[i];
    const Eigen::Vector3d opk = RotationToOpk(im.rotation);
    const ViewFootprint& fp = o.footprints[i];
    char line[512];
    std::snprintf(line, sizeof line,
                  "  %-25s %-8s %13.3f %13.3f %10.3f %8.3f %8.3f %9.3f %7.3f %9.1f %8.1f %5d\n",
                  im.name.substr(0, 25).c_str(), im.camera.substr(0, 8).c_str(), im.position.x(),
                  im.position.y(), im.position.z(), opk(0), opk(1), opk(2), fp.gsd_m,
                  fp.height_above_plane_m, fp.off_nadir_deg, OverlapCount(o, static_cast<int>(i)));
    s << line;
  }
  s << "Overlap graph (" << o.overlaps.size() << " pairs, fraction of the smaller footprint"
    << (o.plane_is_ground ? " on the ground" : " on the scene plane") << "):\n";
  for (const auto& e : o.overlaps) {
    s << "  " << m.images[e.a].name << " -- " << m.images[e.b].name << "  "
      << Fmt("%.0f%%", 100 * e.fraction) << "\n";
  }
  if (!o.warnings.empty()) {
    s << "Warnings:\n";
    for (const auto& w : o.warnings) s << "  " << w << "\n";
  }
  return s.str();
}

nlohmann::json InfoToJson(const BlockInfo& info) {
  using nlohmann::json;
  const BlockManifest& m = info.manifest;
  const BlockOverview& o = info.overview;
  json j;
  j["block"] = m.source;
  j["crs"] = m.crs.empty() ? json(nullptr) : json(m.crs);
  j["local_origin"] = {{"lat", info.block.frame.origin_lat},
                       {"lon", info.block.frame.origin_lon},
                       {"h", info.block.frame.origin_h}};
  j["ground_height"] = m.ground_height ? json(*m.ground_height) : json(nullptr);
  j["dtm"] = m.dtm.empty() ? json(nullptr) : json(m.dtm);
  j["dsm"] = m.dsm.empty() ? json(nullptr) : json(m.dsm);
  j["cameras"] = json::array();
  for (const Camera& c : m.cameras) {
    j["cameras"].push_back({{"id", c.id},
                            {"width", c.width},
                            {"height", c.height},
                            {"fx", c.fx},
                            {"fy", c.fy},
                            {"cx", c.cx},
                            {"cy", c.cy},
                            {"distortion", c.HasDistortion()}});
  }
  j["images"] = json::array();
  for (size_t i = 0; i < m.images.size(); ++i) {
    const ManifestImage& im = m.images[i];
    const ViewFootprint& fp = o.footprints[i];
    const Eigen::Vector3d opk = RotationToOpk(im.rotation);
    j["images"].push_back({{"name", im.name},
                           {"path", im.path},
                           {"camera", im.camera},
                           {"position", {im.position.x(), im.position.y(), im.position.z()}},
                           {"opk", {opk(0), opk(1), opk(2)}},
                           {"gsd_m", fp.gsd_m},
                           {"height_above_ground_m", fp.height_above_plane_m},
                           {"off_nadir_deg", fp.off_nadir_deg},
                           {"footprint_area_m2", fp.area_m2},
                           {"overlaps", OverlapCount(o, static_cast<int>(i))}});
  }
  j["footprint_plane"] = o.plane_is_ground ? "ground" : "scene";
  j["overlaps"] = json::array();
  for (const auto& e : o.overlaps) {
    j["overlaps"].push_back(
        {{"a", m.images[e.a].name}, {"b", m.images[e.b].name}, {"fraction", e.fraction}});
  }
  j["warnings"] = o.warnings;
  return j;
}

std::string FormatTiles(const BlockInfo& info, double size, bool json) {
  const std::vector<Eigen::Vector4d> grid =
      TileGrid(info.overview.footprints, ManifestLocalFrame(info.manifest), size);
  if (json) {
    nlohmann::json a = nlohmann::json::array();
    for (const Eigen::Vector4d& t : grid) a.push_back({t[0], t[1], t[2], t[3]});
    return a.dump() + "\n";
  }
  std::string out;
  for (const Eigen::Vector4d& t : grid)
    out += StrFormat("%.10g,%.10g,%.10g,%.10g\n", t[0], t[1], t[2], t[3]);
  return out;
}

}  // namespace roofsweep
