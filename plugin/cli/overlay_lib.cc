#include "plugin/cli/overlay_lib.h"

#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "algorithms/core/error.h"
#include "algorithms/core/format.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/output_file.h"
#include "io/citymodel/reproject.h"
#include "io/core/block_manifest.h"
#include "io/core/crs_identity.h"
#include "io/core/image_io.h"
#include "io/core/local_frame.h"
#include "io/orientation/block_source.h"

namespace roofsweep {
namespace {

namespace fs = std::filesystem;

nlohmann::json SupportJson(const EdgeSupport& s) {
  const double f = s.Fraction();
  return {{"visible_px", s.visible_px},
          {"supported_px", s.supported_px},
          {"hidden_px", s.hidden_px},
          {"supported_fraction", std::isfinite(f) ? nlohmann::json(f) : nlohmann::json()}};
}

void WriteReport(const std::string& path, const OverlaySummary& s) {
  nlohmann::json j;
  j["total"] = SupportJson(s.total);
  j["views"] = nlohmann::json::array();
  for (const auto& v : s.views)
    j["views"].push_back({{"view", v.view}, {"file", v.file}, {"roof_edges", SupportJson(v.roof)}});
  j["buildings"] = nlohmann::json::array();
  for (const auto& b : s.buildings)
    j["buildings"].push_back({{"id", b.id},
                              {"x", std::isfinite(b.x) ? nlohmann::json(b.x) : nlohmann::json()},
                              {"y", std::isfinite(b.y) ? nlohmann::json(b.y) : nlohmann::json()},
                              {"views", b.views},
                              {"roof_edges", SupportJson(b.roof)}});
  j["messages"] = s.messages;
  // An existing file was refused before the work.
  WriteTextFile(path, j.dump(2) + "\n", /*overwrite=*/true);
}

std::string PngName(const std::string& view) {
  std::string name = view;
  for (char& c : name)
    if (c == '/' || c == '\\') c = '_';
  return name + ".png";
}

}  // namespace

OverlaySummary RunOverlay(const OverlayRequest& r, Progress& progress) {
  const auto t_start = std::chrono::steady_clock::now();
  if (r.output_dir.empty()) throw Error("overlay: no output folder given (-o)");
  if (!(r.options.search_px >= 0) || !(r.options.step_px > 0) ||
      !(r.options.max_angle_deg > 0 && r.options.max_angle_deg <= 90))
    throw Error("overlay: -search_px must be >= 0 and -max_angle in (0, 90]");
  const BlockManifest manifest = OpenBlockManifest(r.block);
  const Block block = ManifestToBlock(manifest);
  const LocalFrame frame = ManifestLocalFrame(manifest);

  std::vector<int> views;
  if (r.views.empty()) {
    for (size_t i = 0; i < block.views.size(); ++i) views.push_back(static_cast<int>(i));
  } else {
    std::set<int> chosen;
    for (const std::string& name : r.views) {
      const int v = block.FindView(name);
      if (v < 0) throw Error(r.block + ": the block has no view named '" + name + "'");
      chosen.insert(v);
    }
    views.assign(chosen.begin(), chosen.end());  // block order
  }
  if (views.empty()) throw Error(r.block + ": the block has no images");

  // Every output checked before any work: an existing PNG without
  // overwrite refuses the whole run, not the view it belongs to.
  std::error_code ec;
  fs::create_directories(r.output_dir, ec);
  if (ec || !fs::is_directory(r.output_dir))
    throw Error(r.output_dir + ": cannot create the output folder" +
                (ec ? ": " + ec.message() : std::string()));
  std::vector<std::string> files(views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    files[i] = (fs::path(r.output_dir) / PngName(block.views[views[i]].name)).string();
    CheckOutputPath(files[i], r.overwrite);
  }
  if (!r.report.empty()) CheckOutputPath(r.report, r.overwrite);

  OverlaySummary out;
  CityModel model = ReadCityModel(r.model);
  if (model.buildings.empty()) throw Error(r.model + ": the model has no buildings");
  if (!manifest.crs.empty()) {
    if (model.crs.empty()) {
      out.messages.push_back(r.model + ": no CRS; taken to be the block's " + manifest.crs);
    } else if (!SameHorizontalCrs(model.crs, manifest.crs)) {
      const std::string from = model.crs;
      try {
        ReprojectCityModel(model, manifest.crs);
      } catch (const Error& e) {
        throw Error(r.model + ": " + e.what());
      }
      out.messages.push_back(r.model + ": reprojected from " + from + " to the block's " +
                             manifest.crs);
    }
  }
  std::vector<Eigen::Vector2d> centres;
  for (const Building& b : model.buildings) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int n = 0;
    for (const Building* s : b.Solids())
      for (const Surface& surface : s->surfaces)
        if (surface.type == SurfaceType::kRoof)
          for (const Polygon3& p : surface.polygons)
            for (const Eigen::Vector3d& v : p.exterior) {
              sum += v.head<2>();
              ++n;
            }
    centres.push_back(n > 0 ? Eigen::Vector2d(sum / n) : Eigen::Vector2d(NAN, NAN));
  }
  model.TransformVertices([&](const Eigen::Vector3d& v) { return frame.ToLocal(v); });
  for (const Building& b : model.buildings)
    for (const Building* s : b.Solids())
      for (const Surface& surface : s->surfaces)
        for (const Polygon3& p : surface.polygons)
          for (const Eigen::Vector3d& v : p.exterior)
            if (!v.allFinite())
              throw Error(r.model + ": building " + b.id +
                          " has a vertex that is not a finite number");

  const std::vector<ModelEdge> edges = ModelEdges(model);
  const ModelOccluder occluder(model);
  const int nb = static_cast<int>(model.buildings.size());

  // Every image readable before any overlay is written.
  std::vector<std::exception_ptr> errors(views.size());
  tbb::parallel_for(size_t{0}, views.size(), [&](size_t i) {
    try {
      CheckImageReadable(block.views[views[i]].image_path);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  out.views.resize(views.size());
  std::vector<std::vector<EdgeSupport>> per_building(views.size());
  std::mutex progress_mutex;
  int done = 0;
  bool cancelled = false;
  tbb::parallel_for(size_t{0}, views.size(), [&](size_t i) {
    try {
      {
        std::lock_guard<std::mutex> lock(progress_mutex);
        if (cancelled) return;
      }
      const View& view = block.views[views[i]];
      const Camera& camera = block.CameraOf(view);
      const cv::Mat image = ReadImage(view.image_path);
      if (image.cols != camera.width || image.rows != camera.height)
        throw Error(view.image_path + ": image is " + std::to_string(image.cols) + " x " +
                    std::to_string(image.rows) + " px, its camera " + std::to_string(camera.width) +
                    " x " + std::to_string(camera.height));
      ImageOverlay o = OverlayModel(image, camera, view.pose, edges, nb, occluder, r.options);
      WriteImage(files[i], o.drawing);
      out.views[i] = {view.name, files[i], o.roof};
      per_building[i] = std::move(o.per_building);
      std::lock_guard<std::mutex> lock(progress_mutex);
      ++done;
      if (!progress.Update(0.99 * done / static_cast<double>(views.size()), "overlay"))
        cancelled = true;
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  if (cancelled) throw Cancelled{};
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  // Sums in block order, so that the figures do not depend on the schedule.
  out.buildings.resize(model.buildings.size());
  for (int b = 0; b < nb; ++b) {
    out.buildings[b].id = model.buildings[b].id;
    out.buildings[b].x = centres[b].x();
    out.buildings[b].y = centres[b].y();
  }
  for (size_t i = 0; i < views.size(); ++i) {
    out.total += out.views[i].roof;
    for (int b = 0; b < nb; ++b) {
      out.buildings[b].roof += per_building[i][b];
      out.buildings[b].views += per_building[i][b].visible_px > 0;
    }
  }
  if (!r.report.empty()) WriteReport(r.report, out);
  progress.Update(1.0, "done");
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return out;
}

std::string FormatOverlaySummary(const OverlaySummary& s) {
  auto pct = [](const EdgeSupport& e) {
    const double f = e.Fraction();
    return std::isfinite(f) ? StrFormat("%5.1f %%", 100 * f) : std::string("    n/a");
  };
  std::ostringstream o;
  for (const std::string& m : s.messages) o << m << "\n";
  o << "Roof edges of the model on an image edge (visible length; hidden by the model itself "
       "not counted):\n";
  o << StrFormat("  %-24s %10s %10s %9s\n", "view", "visible px", "hidden px", "on edge");
  for (const auto& v : s.views)
    o << StrFormat("  %-24s %10.0f %10.0f %9s\n", v.view.c_str(), v.roof.visible_px,
                   v.roof.hidden_px, pct(v.roof).c_str());
  o << StrFormat("  %-24s %10.0f %10.0f %9s\n", "all views", s.total.visible_px, s.total.hidden_px,
                 pct(s.total).c_str());
  // The buildings a person should look at first: the least supported of
  // those seen over a fair length (at least 100 px, so a shed's few pixels
  // do not crowd out a house).
  std::vector<const OverlayBuildingSummary*> seen;
  for (const auto& b : s.buildings)
    if (b.roof.visible_px >= 100) seen.push_back(&b);
  std::stable_sort(seen.begin(), seen.end(), [](const auto* a, const auto* b) {
    return a->roof.Fraction() < b->roof.Fraction();
  });
  const size_t n = std::min<size_t>(seen.size(), 5);
  if (n > 0) {
    o << "Least supported buildings (" << seen.size() << " seen over 100 px or more):\n";
    for (size_t i = 0; i < n; ++i)
      o << StrFormat("  %-20s %s on edge over %6.0f px in %2d views, at %.2f %.2f\n",
                     seen[i]->id.c_str(), pct(seen[i]->roof).c_str(), seen[i]->roof.visible_px,
                     seen[i]->views, seen[i]->x, seen[i]->y);
  }
  o << StrFormat("Time: %.1f s\n", s.seconds);
  return o.str();
}

}  // namespace roofsweep
