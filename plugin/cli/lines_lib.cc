#include "plugin/cli/lines_lib.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "algorithms/core/error.h"
#include "algorithms/edges/extract_segments.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/output_file.h"
#include "io/core/block_manifest.h"
#include "io/core/image_io.h"
#include "io/core/manifest_paths.h"
#include "io/orientation/block_source.h"
#include "plugin/cli/tile_lib.h"

namespace roofsweep {
namespace {

namespace fs = std::filesystem;

const char* kLayerDescription =
    "Straight colour edge segments (roofsweep lines, Scholze et al. 2000). Coordinates are image "
    "pixels: x right, y down, origin at the top-left corner of the top-left pixel (pixel (0,0) "
    "covers [0,1)x[0,1)); no CRS. Walking from the first to the last vertex, the brighter side "
    "is on the left.";

const char* MethodName(GradientMethod m) {
  switch (m) {
    case GradientMethod::kMax:
      return "max";
    case GradientMethod::kDiZenzo:
      return "dizenzo";
    case GradientMethod::kGrey:
      return "grey";
  }
  return "?";
}

const char* BandName(EdgeBand b) {
  switch (b) {
    case EdgeBand::kRed:
      return "red";
    case EdgeBand::kGreen:
      return "green";
    case EdgeBand::kBlue:
      return "blue";
    case EdgeBand::kFused:
      return "fused";
    case EdgeBand::kGrey:
      return "grey";
  }
  return "?";
}

std::string Hex(const Eigen::Vector3f& c) {
  char buf[8];
  auto b = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.f, 1.f) * 255)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", b(c.x()), b(c.y()), b(c.z()));
  return buf;
}

LayerFeature ToFeature(const Segment2D& s) {
  LayerFeature f;
  f.lines.push_back(
      {Eigen::Vector3d(s.p0.x(), s.p0.y(), 0), Eigen::Vector3d(s.p1.x(), s.p1.y(), 0)});
  const Eigen::Vector2d d = s.p1 - s.p0;
  f.reals["length_px"] = s.Length();
  f.reals["direction_deg"] = std::atan2(d.y(), d.x()) * 180.0 / M_PI;
  f.reals["contrast"] = s.contrast;
  f.reals["rms_residual_px"] = s.rms_residual;
  f.integers["support"] = s.support;
  f.integers["texture"] = s.texture;
  f.integers["scale"] = s.scale;
  f.strings["band"] = BandName(s.band);
  f.strings["method"] = MethodName(s.method);
  f.strings["colour_left"] = Hex(s.colour_left);
  f.strings["colour_right"] = Hex(s.colour_right);
  return f;
}

// The image as 8-bit RGB with the segments drawn in yellow (rarely a roof
// or ground colour), those marked as texture in cyan, 1 px anti-aliased.
cv::Mat Overlay(const cv::Mat& image, const Segments2D& segments) {
  cv::Mat rgb;
  if (image.channels() == 1)
    cv::cvtColor(image, rgb, cv::COLOR_GRAY2RGB);
  else
    rgb = image;
  cv::Mat out;
  rgb.convertTo(out, CV_8UC3, 255.0);
  constexpr int kShift = 4;  // sub-pixel drawing, 1/16 px
  auto pt = [](const Eigen::Vector2d& p) {
    // OpenCV draws with integer coordinates at pixel centres.
    return cv::Point(static_cast<int>(std::lround((p.x() - 0.5) * (1 << kShift))),
                     static_cast<int>(std::lround((p.y() - 0.5) * (1 << kShift))));
  };
  for (const Segment2D& s : segments) {
    const cv::Scalar colour = s.texture ? cv::Scalar(0, 255, 255) : cv::Scalar(255, 255, 0);
    cv::line(out, pt(s.p0), pt(s.p1), colour, 1, cv::LINE_AA, kShift);
  }
  return out;
}

double MsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::string LinesLayerName(const std::string& image_path) {
  std::string stem = fs::path(image_path).stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  return "lines_" + stem;
}

LinesSummary RunLines(const LinesRequest& r, Progress& progress) {
  const auto t_start = std::chrono::steady_clock::now();
  if (r.output.empty()) throw Error("lines: no output file given (-o)");
  FeatureLayerOptions lo;
  lo.driver = r.format;
  lo.overwrite = r.overwrite;
  lo.dataset_options = r.dataset_options;
  lo.layer_options = r.layer_options;
  // Refuse an existing output, an unknown format or bad creation options
  // before the work, not after it.
  CheckFeatureLayerOutput(r.output, lo);
  BlockManifest manifest = OpenBlockManifest(r.block);
  if (manifest.images.empty()) throw Error(r.block + ": the block has no images");
  if (r.aoi) manifest.aoi = r.aoi;
  if (!r.png_dir.empty()) {
    std::error_code ec;
    fs::create_directories(r.png_dir, ec);
    if (ec || !fs::is_directory(r.png_dir))
      throw Error(r.png_dir + ": cannot create the overlay folder" +
                  (ec ? ": " + ec.message() : std::string()));
  }

  const size_t n = manifest.images.size();
  std::vector<std::string> paths(n), layers(n);
  std::map<std::string, int> used;  // lower-case name -> count (GPKG names ignore case)
  for (size_t i = 0; i < n; ++i) {
    paths[i] = manifest_paths::Resolve(manifest.images[i].path, manifest.base_dir);
    std::string name = LinesLayerName(paths[i]);
    auto lower = [](std::string s) {
      for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return s;
    };
    std::string candidate = name;
    for (int k = 2; used.count(lower(candidate)); ++k) candidate = name + "_" + std::to_string(k);
    used[lower(candidate)] = 1;
    layers[i] = candidate;
  }

  LinesSummary out;
  // The images to process (manifest indices); with a tile, the windows of
  // those that see it, read here.
  std::vector<size_t> todo;
  std::vector<cv::Mat> tile_images(n);
  std::vector<PixelWindow> window(n);
  if (manifest.aoi) {
    if (!(r.tile_buffer_m >= 0)) throw Error("lines: the tile buffer must be 0 m or more");
    Block block = ManifestToBlock(manifest);
    const TileCut tile = CutBlockToTile(&block, r.tile_buffer_m, r.block);
    std::vector<cv::Mat> images = ReadBlockImages(block, &tile, r.block);
    out.tile = tile.message;
    std::map<std::string, size_t> index;
    for (size_t i = 0; i < n; ++i) index.emplace(manifest.images[i].name, i);
    for (size_t v = 0; v < block.views.size(); ++v) {
      const auto it = index.find(block.views[v].name);
      if (it == index.end()) continue;
      todo.push_back(it->second);
      tile_images[it->second] = std::move(images[v]);
      if (tile.Windowed()) window[it->second] = tile.windows[v];
    }
    std::sort(todo.begin(), todo.end());
  } else {
    // Header and last block of every image first: a missing or truncated
    // one refuses the block before any overlay is written.
    std::vector<std::exception_ptr> errors(n);
    tbb::parallel_for(size_t{0}, n, [&](size_t i) {
      try {
        CheckImageReadable(paths[i]);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    });
    for (const auto& e : errors)
      if (e) std::rethrow_exception(e);
    for (size_t i = 0; i < n; ++i) todo.push_back(i);
  }

  const size_t m = todo.size();
  std::vector<std::exception_ptr> errors(m);
  out.images.resize(m);
  std::vector<FeatureLayerData> data(m);
  std::mutex progress_mutex;
  int done = 0;
  bool cancelled = false;
  tbb::parallel_for(size_t{0}, m, [&](size_t k) {
    const size_t i = todo[k];
    try {
      {
        std::lock_guard<std::mutex> lock(progress_mutex);
        if (cancelled) return;
      }
      const auto t0 = std::chrono::steady_clock::now();
      const cv::Mat image = tile_images[i].empty() ? ReadImage(paths[i]) : tile_images[i];
      Segments2D segments;
      try {
        segments = ExtractSegments(image, r.edges);
      } catch (const Error& e) {
        throw Error(paths[i] + ": " + e.what());
      }
      LinesImageSummary& s = out.images[k];
      s.ms = MsSince(t0);
      s.image = manifest.images[i].name;
      s.layer = layers[i];
      s.width = image.cols;
      s.height = image.rows;
      s.bands = image.channels();
      s.segments = static_cast<int>(segments.size());
      FeatureLayerData& d = data[k];
      d.name = layers[i];
      d.geometry = LayerGeometry::kLineString;
      const PixelWindow& w = window[i];
      d.description =
          std::string(kLayerDescription) + " Image: " + paths[i] +
          (w.width > 0
               ? " (its window of " + std::to_string(w.width) + " x " + std::to_string(w.height) +
                     " px at x " + std::to_string(w.x) + ", y " + std::to_string(w.y) +
                     ", read for one tile)."
               : " (" + std::to_string(image.cols) + " x " + std::to_string(image.rows) + " px).");
      if (!r.png_dir.empty())
        WriteImage((fs::path(r.png_dir) / (layers[i] + ".png")).string(), Overlay(image, segments));
      // Into the whole image's pixels: the window's pixel (0, 0) is the
      // image's (w.x, w.y).
      const Eigen::Vector2d shift(w.x, w.y);
      d.features.reserve(segments.size());
      for (Segment2D seg : segments) {
        seg.p0 += shift;
        seg.p1 += shift;
        d.features.push_back(ToFeature(seg));
      }
      std::lock_guard<std::mutex> lock(progress_mutex);
      ++done;
      if (!progress.Update(0.95 * done / static_cast<double>(m), "lines")) cancelled = true;
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  if (cancelled) throw Cancelled{};
  // The first failing image in block order, whatever the thread schedule.
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  WriteFeatureLayers(r.output, data, lo);
  progress.Update(1.0, "done");
  out.seconds = MsSince(t_start) / 1000.0;
  return out;
}

std::string FormatLinesSummary(const LinesSummary& s) {
  std::ostringstream o;
  if (!s.tile.empty()) o << s.tile << "\n";
  int total = 0;
  for (const LinesImageSummary& i : s.images) {
    char buf[300];
    std::snprintf(buf, sizeof buf, "%-24s %5d x %-5d %d band%s %7d segments %8.0f ms\n",
                  i.layer.c_str(), i.width, i.height, i.bands, i.bands == 1 ? " " : "s", i.segments,
                  i.ms);
    o << buf;
    total += i.segments;
  }
  char buf[200];
  std::snprintf(buf, sizeof buf, "%zu images, %d segments in %.1f s\n", s.images.size(), total,
                s.seconds);
  o << buf;
  return o.str();
}

}  // namespace roofsweep
