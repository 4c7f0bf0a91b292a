// Manifest checks and the conversion of a manifest into a Block in the
// local frame. JSON reading and writing live in block_manifest_json.cc.

#include "io/core/block_manifest.h"

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "algorithms/geometry/terrain_filter.h"
#include "algorithms/geometry/view.h"
#include "io/core/dtm_grid.h"
#include "io/core/image_io.h"
#include "io/core/local_frame.h"
#include "io/core/manifest_paths.h"

namespace fs = std::filesystem;

namespace roofsweep {
namespace {

// Rotations read from files carry 8-10 significant digits.
constexpr double kRotationTolerance = 1e-6;

// How far beyond the flying height an image's ground footprint is followed
// for oblique views whose upper corners see the horizon.
constexpr double kMaxFootprintRangeFactor = 10.0;

std::string Where(const BlockManifest& m) { return m.source.empty() ? "manifest" : m.source; }

[[noreturn]] void Fail(const BlockManifest& m, const std::string& pointer,
                       const std::string& what) {
  throw Error(Where(m) + ": " + pointer + ": " + what);
}

std::string Index(const std::string& array, size_t i) {
  return "/" + array + "/" + std::to_string(i);
}

Eigen::Vector3d MeanPosition(const BlockManifest& m) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const ManifestImage& im : m.images) sum += im.position;
  return sum / static_cast<double>(m.images.size());
}

// Ground footprint of all views in the local frame on the plane z = ground,
// as (min x, min y, max x, max y).
Eigen::Vector4d FootprintBox(const Block& block, double ground) {
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const View& v : block.views) {
    const Camera& cam = block.CameraOf(v);
    const double range = kMaxFootprintRangeFactor * std::max(1.0, std::abs(v.pose.C.z() - ground));
    lo = lo.cwiseMin(v.pose.C.head<2>());
    hi = hi.cwiseMax(v.pose.C.head<2>());
    for (const Eigen::Vector2d& px :
         {Eigen::Vector2d(0, 0), Eigen::Vector2d(cam.width, 0),
          Eigen::Vector2d(cam.width, cam.height), Eigen::Vector2d(0, cam.height)}) {
      const Ray ray = BackProject(cam, v.pose, px);
      Eigen::Vector3d hit;
      const std::optional<Eigen::Vector3d> on_plane = IntersectHorizontalPlane(ray, ground);
      if (on_plane && (on_plane->head<2>() - ray.origin.head<2>()).norm() <= range) {
        hit = *on_plane;
      } else {
        // Looking at or above the horizon: follow the ray's heading.
        Eigen::Vector2d dir = ray.direction.head<2>();
        if (dir.norm() < 1e-12) continue;
        hit.head<2>() = ray.origin.head<2>() + range * dir.normalized();
      }
      lo = lo.cwiseMin(hit.head<2>());
      hi = hi.cwiseMax(hit.head<2>());
    }
  }
  return {lo.x(), lo.y(), hi.x(), hi.y()};
}

}  // namespace

int BlockManifest::FindCamera(const std::string& id) const {
  for (size_t i = 0; i < cameras.size(); ++i) {
    if (cameras[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

void ValidateManifest(const BlockManifest& m, bool check_images) {
  if (m.height_type != "ellipsoidal" && m.height_type != "orthometric") {
    Fail(m, "/height_type",
         "must be \"ellipsoidal\" or \"orthometric\", not \"" + m.height_type + "\"");
  }
  if (!std::isfinite(m.geoid_undulation)) Fail(m, "/geoid_undulation", "is not a finite number");
  if (m.height_type == "ellipsoidal" && m.geoid_undulation != 0) {
    Fail(m, "/geoid_undulation",
         "applies to orthometric heights only (height_type is ellipsoidal)");
  }
  if (m.cameras.empty()) Fail(m, "/cameras", "no cameras");
  if (m.images.empty()) Fail(m, "/images", "no images");
  std::map<std::string, size_t> camera_ids;
  for (size_t i = 0; i < m.cameras.size(); ++i) {
    const Camera& c = m.cameras[i];
    if (c.id.empty()) Fail(m, Index("cameras", i) + "/id", "is empty");
    const auto [it, fresh] = camera_ids.emplace(c.id, i);
    if (!fresh) {
      Fail(m, Index("cameras", i) + "/id",
           "duplicate camera id '" + c.id + "' (also " + Index("cameras", it->second) + "/id)");
    }
    c.Validate(Where(m) + ": " + Index("cameras", i));
    if (!std::isfinite(c.pixel_size_mm) || c.pixel_size_mm < 0) {
      Fail(m, Index("cameras", i) + "/pixel_size_mm", "must be a finite number >= 0");
    }
  }
  std::map<std::string, size_t> names;
  for (size_t i = 0; i < m.images.size(); ++i) {
    const ManifestImage& im = m.images[i];
    const std::string at = Index("images", i);
    if (im.name.empty()) Fail(m, at + "/name", "is empty");
    const auto [it, fresh] = names.emplace(im.name, i);
    if (!fresh) {
      Fail(
          m, at + "/name",
          "duplicate image name '" + im.name + "' (also " + Index("images", it->second) + "/name)");
    }
    if (im.path.empty()) Fail(m, at + "/path", "is empty");
    const int cam = m.FindCamera(im.camera);
    if (cam < 0) Fail(m, at + "/camera", "unknown camera '" + im.camera + "'");
    if (!im.position.allFinite()) Fail(m, at + "/position", "is not finite (NaN or infinite)");
    if (!im.rotation.allFinite()) Fail(m, at + "/rotation", "is not finite (NaN or infinite)");
    const double ortho =
        (im.rotation.transpose() * im.rotation - Eigen::Matrix3d::Identity()).norm();
    if (ortho > kRotationTolerance || im.rotation.determinant() < 0) {
      Fail(m, at + "/rotation",
           "is not a rotation matrix (|RᵀR - I| = " + std::to_string(ortho) +
               ", det = " + std::to_string(im.rotation.determinant()) + ")");
    }
    if (check_images) {
      const std::string file = manifest_paths::Resolve(im.path, m.base_dir);
      ImageInfo info;
      try {
        info = ProbeImage(file);
      } catch (const Error& e) {
        Fail(m, at + "/path", e.what());
      }
      const Camera& c = m.cameras[static_cast<size_t>(cam)];
      if (info.width != c.width || info.height != c.height) {
        Fail(m, at,
             file + " is " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                 " pixels but camera '" + c.id + "' is " + std::to_string(c.width) + "x" +
                 std::to_string(c.height));
      }
      try {
        CheckImageReadable(file);
      } catch (const Error& e) {
        Fail(m, at + "/path", e.what());
      }
    }
  }
  if (!m.dtm.empty() && !m.dsm.empty()) Fail(m, "/ground/dsm", "and /ground/dtm: give one of them");
  if (!(m.terrain_window_m > 0) || !std::isfinite(m.terrain_window_m))
    Fail(m, "/ground/terrain_window_m", "must be a positive number of metres");
  if (m.ground_height && !std::isfinite(*m.ground_height)) {
    Fail(m, "/ground/height", "is not a finite number");
  }
  if (!std::isfinite(m.max_building_height) || m.max_building_height <= 0) {
    Fail(m, "/max_building_height", "must be a positive number");
  }
  if (m.aoi) {
    const Eigen::Vector4d& a = *m.aoi;
    if (!a.allFinite() || !(a[0] < a[2]) || !(a[1] < a[3])) {
      Fail(m, "/aoi", "must be finite [min x, min y, max x, max y] with min < max");
    }
  }
}

// The raster the ground comes from: the DTM, or the surface model it is
// derived from.
static const std::string& GroundRaster(const BlockManifest& m) {
  return m.dtm.empty() ? m.dsm : m.dtm;
}

// Origin of the local frame: under the middle of the block, on the ground
// where it is known.
static Eigen::Vector3d FrameOrigin(const BlockManifest& m, DtmRaster* dtm) {
  const Eigen::Vector3d mean = MeanPosition(m);
  Eigen::Vector3d origin = mean;
  if (m.ground_height) {
    origin.z() = *m.ground_height;
  } else if (dtm) {
    const double h = dtm->SampleCrsPoint(mean.head<2>());
    origin.z() = std::isfinite(h) ? h : 0.5 * (dtm->min_height() + dtm->max_height());
  }
  return origin;
}

LocalFrame ManifestLocalFrame(const BlockManifest& m) {
  std::unique_ptr<DtmRaster> dtm;
  if (!GroundRaster(m).empty() && !m.ground_height)
    dtm = std::make_unique<DtmRaster>(manifest_paths::Resolve(GroundRaster(m), m.base_dir), m.crs);
  const double undulation = m.height_type == "orthometric" ? m.geoid_undulation : 0.0;
  return LocalFrame(m.crs, FrameOrigin(m, dtm.get()), undulation);
}

GroundModel ManifestGroundInCrs(const BlockManifest& m, const Eigen::Vector4d& bbox) {
  GroundModel ground;
  if (m.ground_height) ground.height = *m.ground_height;
  if (GroundRaster(m).empty()) return ground;
  DtmRaster dtm(manifest_paths::Resolve(GroundRaster(m), m.base_dir), m.crs);
  // Resampled as for ManifestToBlock, in a frame without a CRS (the
  // identity), a cell beyond the box all round so that HeightAt interpolates
  // up to its border instead of holding the outermost cell centres' heights.
  const double d = dtm.cell_size();
  try {
    const GroundModel::Grid g = ResampleDtm(dtm, LocalFrame("", Eigen::Vector3d::Zero()),
                                            bbox + Eigen::Vector4d(-d, -d, d, d));
    ground.grid = m.dsm.empty() ? g : TerrainFromSurfaceModel(g, m.terrain_window_m);
  } catch (const Error& e) {
    throw Error(Where(m) + (m.dsm.empty() ? ": /ground/dtm: " : ": /ground/dsm: ") + e.what());
  }
  return ground;
}

Block ManifestToBlock(const BlockManifest& m) {
  ValidateManifest(m, false);
  const double undulation = m.height_type == "orthometric" ? m.geoid_undulation : 0.0;

  std::unique_ptr<DtmRaster> dtm;
  if (!GroundRaster(m).empty())
    dtm = std::make_unique<DtmRaster>(manifest_paths::Resolve(GroundRaster(m), m.base_dir), m.crs);

  const Eigen::Vector3d origin = FrameOrigin(m, dtm.get());
  LocalFrame frame = [&] {
    try {
      return LocalFrame(m.crs, origin, undulation);
    } catch (const Error& e) {
      throw Error(Where(m) + ": /crs: " + e.what());
    }
  }();

  Block block;
  block.source = m.source;
  block.frame = frame.Info();
  block.cameras = m.cameras;
  block.max_building_height = m.max_building_height;
  for (const ManifestImage& im : m.images) {
    View v;
    v.name = im.name;
    v.image_path = manifest_paths::Resolve(im.path, m.base_dir);
    v.camera = m.FindCamera(im.camera);
    v.pose.C = frame.ToLocal(im.position);
    // OPK refers to the grid axes at the camera, which lean against the
    // local ENU axes by the convergence (and by the earth's curvature).
    v.pose.R = PatbToCv(frame.GridToLocal(im.position) * im.rotation);
    block.views.push_back(v);
  }

  if (m.ground_height) {
    block.ground.height = frame.ToLocal({origin.x(), origin.y(), *m.ground_height}).z();
  }
  if (dtm) {
    const double low = frame.ToLocal({origin.x(), origin.y(), dtm->min_height()}).z();
    Eigen::Vector4d box = FootprintBox(block, low);
    // The opening is exact only half a window inside the grid: read the
    // surface model a window beyond the footprints where it reaches.
    if (!m.dsm.empty()) box += Eigen::Vector4d(-1, -1, 1, 1) * m.terrain_window_m;
    // Only where the DTM has data.
    Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const Eigen::Vector2d& p : dtm->OutlineCrs()) {
      const Eigen::Vector3d l = frame.ToLocal({p.x(), p.y(), dtm->min_height()});
      lo = lo.cwiseMin(l.head<2>());
      hi = hi.cwiseMax(l.head<2>());
    }
    box = Eigen::Vector4d(std::max(box[0], lo.x()), std::max(box[1], lo.y()),
                          std::min(box[2], hi.x()), std::min(box[3], hi.y()));
    try {
      block.ground.grid = ResampleDtm(*dtm, frame, box);
      if (!m.dsm.empty()) {
        block.surface = block.ground.grid;
        block.ground.grid = TerrainFromSurfaceModel(*block.surface, m.terrain_window_m);
      }
    } catch (const Error& e) {
      throw Error(Where(m) + (m.dsm.empty() ? ": /ground/dtm: " : ": /ground/dsm: ") + e.what());
    }
  }

  if (!m.footprints.empty())
    block.footprints_path = manifest_paths::Resolve(m.footprints, m.base_dir);
  block.footprints_layer = m.footprints_layer;
  if (m.aoi) {
    const Eigen::Vector4d& a = *m.aoi;
    Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const Eigen::Vector2d& c : {Eigen::Vector2d(a[0], a[1]), Eigen::Vector2d(a[2], a[1]),
                                     Eigen::Vector2d(a[2], a[3]), Eigen::Vector2d(a[0], a[3])}) {
      const Eigen::Vector3d l = frame.ToLocal({c.x(), c.y(), origin.z()});
      lo = lo.cwiseMin(l.head<2>());
      hi = hi.cwiseMax(l.head<2>());
    }
    block.aoi = Eigen::Vector4d(lo.x(), lo.y(), hi.x(), hi.y());
  }
  return block;
}

}  // namespace roofsweep
