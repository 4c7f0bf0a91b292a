#include "plugin/cli/tile_lib.h"

#include <cpl_conv.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/core/error.h"
#include "algorithms/core/format.h"
#include "io/core/image_io.h"

namespace roofsweep {
namespace {

// Image filters, flanking regions and correlation windows reach this far
// beyond the image of the region (pixels).
constexpr int kWindowMarginPx = 48;

// Peak resident memory of `run` per pixel read, and what it needs besides:
// 1.25 GB for 33.5 megapixels (realistic, eight 2048 x 2048 views) and
// 0.11 GB for 1 megapixel, rounded up.
constexpr double kRunBytesPerPixel = 40;
constexpr double kRunBaseBytes = 0.2e9;

void Rename(Building* b, const std::string& prefix, std::map<std::string, std::string>* renamed) {
  const std::string id = prefix + b->id;
  (*renamed)[b->id] = id;
  b->id = id;
  for (Building& p : b->parts) Rename(&p, prefix, renamed);
}

}  // namespace

void RequireMemoryForImages(long long pixels, int views, const std::string& source) {
  double limit_gb = 0;
  const char* configured = CPLGetConfigOption("ROOFSWEEP_MAX_MEMORY", nullptr);
  if (configured) {
    char* end = nullptr;
    limit_gb = std::strtod(configured, &end);
    if (end == configured || *end != '\0' || !(limit_gb > 0))
      throw Error(StrFormat("ROOFSWEEP_MAX_MEMORY: expected gigabytes, got '%s'", configured));
  } else {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return;  // unknown: no guard
    limit_gb = static_cast<double>(pages) * static_cast<double>(page) / 1e9;
  }
  const double need_gb = (kRunBytesPerPixel * static_cast<double>(pixels) + kRunBaseBytes) / 1e9;
  if (need_gb > limit_gb)
    throw Error(
        StrFormat("%s: the %d images to read hold %.0f megapixels, which need about %.1f "
                  "GB; %s %.1f GB. Run the block in tiles: -aoi MINX,MINY,MAXX,MAXY "
                  "(examples/tiles.sh)",
                  source.c_str(), views, pixels / 1e6, need_gb,
                  configured ? "ROOFSWEEP_MAX_MEMORY allows" : "this machine has", limit_gb));
}

std::vector<Eigen::Vector4d> TileGrid(const std::vector<ViewFootprint>& footprints,
                                      const LocalFrame& frame, double size) {
  if (!(size > 0)) throw Error("tiles: the tile size must be positive");
  std::vector<Ring2> rings;
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (const ViewFootprint& f : footprints) {
    if (!f.valid) continue;
    Ring2 r;
    for (const Eigen::Vector3d& v : f.outline) {
      const Eigen::Vector2d c = frame.ToCrs(v).head<2>();
      r.push_back(c);
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
    if (SignedArea(r) < 0) std::reverse(r.begin(), r.end());
    if (r.size() >= 3) rings.push_back(std::move(r));
  }
  std::vector<Eigen::Vector4d> tiles;
  if (rings.empty()) return tiles;
  const double i0 = std::floor(lo.x() / size), i1 = std::ceil(hi.x() / size);
  const double j0 = std::floor(lo.y() / size), j1 = std::ceil(hi.y() / size);
  if ((i1 - i0) * (j1 - j0) > 1e6)
    throw Error(StrFormat("tiles: %.0f x %.0f tiles of %g; choose a larger tile size", i1 - i0,
                          j1 - j0, size));
  for (double j = j0; j < j1; ++j)
    for (double i = i0; i < i1; ++i) {
      const Ring2 cell = {{i * size, j * size},
                          {(i + 1) * size, j * size},
                          {(i + 1) * size, (j + 1) * size},
                          {i * size, (j + 1) * size}};
      int covering = 0;
      for (const Ring2& r : rings)
        if (std::abs(SignedArea(IntersectConvex(cell, r))) > 1e-9 * size * size) ++covering;
      if (covering >= 2) tiles.emplace_back(i * size, j * size, (i + 1) * size, (j + 1) * size);
    }
  return tiles;
}

std::vector<cv::Mat> ReadBlockImages(const Block& block, const TileCut* tile,
                                     const std::string& source) {
  const bool windowed = tile && tile->Windowed();
  long long pixels = 0;
  if (tile) {
    pixels = tile->pixels_read;
  } else {
    for (const View& v : block.views)
      pixels += static_cast<long long>(block.CameraOf(v).width) * block.CameraOf(v).height;
  }
  RequireMemoryForImages(pixels, static_cast<int>(block.views.size()), source);
  std::vector<cv::Mat> images(block.views.size());
  tbb::parallel_for(size_t{0}, images.size(), [&](size_t v) {
    cv::Rect window;
    if (windowed && v < tile->windows.size()) {
      const PixelWindow& w = tile->windows[v];
      window = cv::Rect(w.x, w.y, w.width, w.height);
    }
    images[v] = ReadImage(block.views[v].image_path, window);
  });
  return images;
}

std::string TileTag(const Eigen::Vector4d& aoi) {
  std::string tag = "t" + StrFormat("%.10g_%.10g", aoi[0], aoi[1]);
  for (char& c : tag)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.' && c != '-') c = '_';
  return tag;
}

TileCut CutBlockToTile(Block* block, double buffer_m, const std::string& source) {
  TileCut cut;
  const Eigen::Vector4d& a = *block->aoi;
  cut.region = Eigen::Vector4d(a[0] - buffer_m, a[1] - buffer_m, a[2] + buffer_m, a[3] + buffer_m);
  // The heights the region spans: the ground under it (a DTM sampled on a
  // 9 x 9 grid) up to the tallest building.
  double z_lo = INFINITY, z_hi = -INFINITY;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double x = cut.region[0] + (cut.region[2] - cut.region[0]) * i / 8.0;
      const double y = cut.region[1] + (cut.region[3] - cut.region[1]) * j / 8.0;
      const double g = block->ground.HeightAt(x, y);
      if (std::isfinite(g)) z_lo = std::min(z_lo, g), z_hi = std::max(z_hi, g);
    }
  long long full = 0, read = 0;
  for (const View& v : block->views)
    full += static_cast<long long>(block->CameraOf(v).width) * block->CameraOf(v).height;
  if (!std::isfinite(z_lo)) {
    cut.message = "tile: no ground height under it; every image is read whole";
    cut.pixels_read = full;
    return cut;
  }
  // A metre of slack below: a DTM interpolated between its posts.
  BlockWindows w = CropBlockToRegion(*block, cut.region, z_lo - 1.0,
                                     z_hi + block->max_building_height, kWindowMarginPx);
  if (w.block.views.empty())
    throw Error(source + ": no image sees the tile (aoi) or the " + StrFormat("%.0f", buffer_m) +
                " m around it");
  for (const PixelWindow& p : w.windows) read += p.Pixels();
  cut.message =
      StrFormat("tile: %zu of %zu views see it and its %.0f m buffer; %.0f of %.0f megapixels read",
                w.block.views.size(), block->views.size(), buffer_m, read / 1e6, full / 1e6);
  *block = std::move(w.block);
  cut.windows = std::move(w.windows);
  cut.pixels_read = read;
  return cut;
}

std::vector<std::string> KeepTileBuildings(const Eigen::Vector4d& aoi, const LocalFrame& frame,
                                           const std::vector<Footprint>& footprints,
                                           AssemblyResult* assembled) {
  // Area and first moments of the footprints, summed over the pieces of an id.
  std::map<std::string, std::pair<double, Eigen::Vector2d>> moments;
  for (const Footprint& f : footprints) {
    auto& [area, moment] = moments.try_emplace(f.id, 0.0, Eigen::Vector2d::Zero()).first->second;
    const double a = SignedArea(f.outline);
    area += std::abs(a);
    moment += (a < 0 ? -1.0 : 1.0) * FirstMoment(f.outline);
  }
  std::vector<std::string> left;
  std::map<std::string, std::string> renamed;
  std::map<std::string, std::string> reason_of;
  const std::string prefix = TileTag(aoi) + "_";
  std::vector<Building> kept;
  for (Building& b : assembled->model.buildings) {
    std::optional<Eigen::Vector2d> c;
    const char* what = "ground centre";
    const auto fp = b.string_attributes.find("footprint_id");
    if (fp != b.string_attributes.end()) {
      const auto m = moments.find(fp->second);
      if (m != moments.end() && m->second.first > 1e-12) {
        c = Eigen::Vector2d(m->second.second / m->second.first);
        what = "footprint's centre";
      }
    }
    if (!c) c = b.PlanCentroid();
    std::string why;
    if (!c) {
      why = "no ground surface to tell its tile";
    } else {
      const double z = std::isfinite(b.GroundZ()) ? b.GroundZ() : 0.0;
      const Eigen::Vector3d p = frame.ToCrs({c->x(), c->y(), z});
      if (!(aoi[0] <= p.x() && p.x() < aoi[2] && aoi[1] <= p.y() && p.y() < aoi[3]))
        why = StrFormat("left to a neighbouring tile: its %s %.2f, %.2f lies outside this one",
                        what, p.x(), p.y());
    }
    if (!why.empty()) {
      for (const Building* s : static_cast<const Building&>(b).Solids()) reason_of[s->id] = why;
      reason_of[b.id] = why;
      left.push_back(b.id + ": " + why);
      continue;
    }
    Rename(&b, prefix, &renamed);
    kept.push_back(std::move(b));
  }
  assembled->model.buildings = std::move(kept);
  for (size_t i = 0; i < assembled->plane_building.size(); ++i) {
    std::string& id = assembled->plane_building[i];
    if (id.empty()) continue;
    if (const auto r = reason_of.find(id); r != reason_of.end()) {
      if (i < assembled->plane_reason.size()) assembled->plane_reason[i] = r->second;
      id.clear();
    } else if (const auto n = renamed.find(id); n != renamed.end()) {
      id = n->second;
    }
  }
  return left;
}

}  // namespace roofsweep
