#include "io/orientation/opensfm_reader.h"

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/orientation/import_common.h"
#include "io/orientation/json_errors.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace roofsweep::orientation {
namespace {

Camera ConvertCamera(const std::string& id, const json& j, const std::string& file,
                     const std::string& pointer) {
  if (!j.is_object()) throw Error(file + ": " + pointer + ": expected an object");
  const std::string type = j.value("projection_type", std::string("perspective"));
  static const std::vector<std::string> kSupported = {"perspective", "brown", "radial",
                                                      "simple_radial"};
  if (std::find(kSupported.begin(), kSupported.end(), type) == kSupported.end()) {
    throw Error(file + ": " + pointer + "/projection_type: '" + type +
                "' is not supported (roofsweep handles frame cameras: perspective, brown, "
                "radial, simple_radial; fisheye and spherical images must be undistorted first)");
  }
  Camera c;
  c.id = id;
  c.width = static_cast<int>(JsonNumber(j, "width", file, pointer));
  c.height = static_cast<int>(JsonNumber(j, "height", file, pointer));
  if (c.width <= 0 || c.height <= 0)
    throw Error(file + ": " + pointer + ": image size must be positive");
  // Normalised coordinates are scaled by max(w, h) and centred on the image
  // centre, with the origin at the centre of the top-left pixel: pixel =
  // s u + (w - 1) / 2. roofsweep's origin is the pixel corner: +0.5.
  const double s = std::max(c.width, c.height);
  double fx, fy;
  if (j.contains("focal")) {
    fx = fy = JsonNumber(j, "focal", file, pointer);
  } else {
    fx = JsonNumber(j, "focal_x", file, pointer);
    fy = JsonNumberOr(j, "focal_y", fx, file, pointer);
  }
  if (!(fx > 0) || !(fy > 0))
    throw Error(file + ": " + pointer + ": zero or negative focal length");
  c.fx = fx * s;
  c.fy = fy * s;
  c.cx = (c.width - 1) / 2.0 + s * JsonNumberOr(j, "c_x", 0, file, pointer) + 0.5;
  c.cy = (c.height - 1) / 2.0 + s * JsonNumberOr(j, "c_y", 0, file, pointer) + 0.5;
  c.k1 = JsonNumberOr(j, "k1", 0, file, pointer);
  c.k2 = JsonNumberOr(j, "k2", 0, file, pointer);
  c.k3 = JsonNumberOr(j, "k3", 0, file, pointer);
  c.p1 = JsonNumberOr(j, "p1", 0, file, pointer);
  c.p2 = JsonNumberOr(j, "p2", 0, file, pointer);
  return c;
}

std::vector<Camera> CamerasOf(const json& cameras, const std::string& file,
                              const std::string& pointer) {
  if (!cameras.is_object()) throw Error(file + ": " + pointer + ": expected an object of cameras");
  std::vector<Camera> out;
  for (const auto& [id, j] : cameras.items()) {
    out.push_back(ConvertCamera(id, j, file, pointer + "/" + PointerToken(id)));
  }
  return out;
}

Eigen::Vector3d Vector3(const json& object, const std::string& key, const std::string& file,
                        const std::string& pointer) {
  const std::string where = file + ": " + pointer + "/" + key;
  if (!object.contains(key)) throw Error(where + ": missing");
  const json& v = object.at(key);
  if (!v.is_array() || v.size() != 3) throw Error(where + ": expected 3 numbers");
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    if (!v[static_cast<size_t>(i)].is_number()) throw Error(where + ": expected 3 numbers");
    out[i] = v[static_cast<size_t>(i)].get<double>();
  }
  return out;
}

// Topocentric ENU at reference_lla -> UTM grid + ellipsoidal height.
class TopocentricToUtm {
 public:
  TopocentricToUtm(double lat0, double lon0, double h0)
      : local_(lat0, lon0, h0, GeographicLib::Geocentric::WGS84()),
        zone_(GeographicLib::UTMUPS::StandardZone(lat0, lon0)),
        north_(lat0 >= 0) {}

  std::string Crs() const { return "EPSG:" + std::to_string((north_ ? 32600 : 32700) + zone_); }
  double Height(const Eigen::Vector3d& enu) const {
    double lat, lon, h;
    local_.Reverse(enu.x(), enu.y(), enu.z(), lat, lon, h);
    return h;
  }
  Eigen::Vector3d Forward(const Eigen::Vector3d& enu) const {
    double lat, lon, h, x, y, gamma, k;
    int zone;
    bool north;
    local_.Reverse(enu.x(), enu.y(), enu.z(), lat, lon, h);
    GeographicLib::UTMUPS::Forward(lat, lon, zone, north, x, y, gamma, k, zone_);
    // A block south of the equator in a northern reference zone (or back)
    // keeps the reference hemisphere's false northing.
    if (north != north_) y += north_ ? -10000000.0 : 10000000.0;
    return {x, y, h};
  }
  // Rotation taking topocentric vectors at `enu` into grid axes (E, N, up
  // there): the polar factor of the numeric Jacobian, which includes the
  // meridian convergence and the earth's curvature between the reference
  // and the point, without sign conventions to get wrong.
  Eigen::Matrix3d GridRotation(const Eigen::Vector3d& enu) const {
    Eigen::Matrix3d J;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d d = Eigen::Vector3d::Unit(i);
      J.col(i) = (Forward(enu + d) - Forward(enu - d)) / 2.0;
    }
    return NearestRotation(J);
  }

 private:
  GeographicLib::LocalCartesian local_;
  int zone_;
  bool north_;
};

}  // namespace

std::vector<Camera> ReadOpenSfmCameras(const std::string& path) {
  const json root = ParseJsonFile(path);
  std::vector<Camera> out;
  if (root.is_array()) {
    for (size_t r = 0; r < root.size(); ++r) {
      const std::string pointer = "/" + std::to_string(r) + "/cameras";
      if (!root[r].is_object() || !root[r].contains("cameras")) {
        throw Error(path + ": " + pointer + ": missing");
      }
      for (auto& c : CamerasOf(root[r].at("cameras"), path, pointer)) {
        if (std::none_of(out.begin(), out.end(), [&](const Camera& o) { return o.id == c.id; }))
          out.push_back(c);
      }
    }
  } else {
    out = CamerasOf(root, path, "");
  }
  if (out.empty()) throw Error(path + ": no cameras");
  return out;
}

BlockManifest ReadOpenSfm(const std::vector<std::string>& sources, const ImportOptions& options) {
  if (sources.size() != 1) throw Error("opensfm: give exactly one reconstruction.json");
  const std::string& path = sources.front();
  const json root = ParseJsonFile(path);
  if (!root.is_array() || root.empty()) {
    throw Error(path + ": expected a non-empty list of reconstructions");
  }
  size_t best = 0, best_shots = 0;
  for (size_t r = 0; r < root.size(); ++r) {
    if (!root[r].is_object() || !root[r].contains("shots") || !root[r].at("shots").is_object()) {
      throw Error(path + ": /" + std::to_string(r) + "/shots: missing or not an object");
    }
    if (root[r].at("shots").size() > best_shots) {
      best = r;
      best_shots = root[r].at("shots").size();
    }
  }
  if (best_shots == 0) throw Error(path + ": no shots in any reconstruction");
  const json& rec = root[best];
  const std::string base = "/" + std::to_string(best);
  if (!rec.contains("cameras")) throw Error(path + ": " + base + "/cameras: missing");

  BlockManifest manifest;
  manifest.cameras = CamerasOf(rec.at("cameras"), path, base + "/cameras");

  std::optional<TopocentricToUtm> to_utm;
  if (rec.contains("reference_lla")) {
    const json& lla = rec.at("reference_lla");
    const std::string p = base + "/reference_lla";
    const double lat = JsonNumber(lla, "latitude", path, p);
    const double lon = JsonNumber(lla, "longitude", path, p);
    const double alt = JsonNumberOr(lla, "altitude", 0, path, p);
    if (std::abs(lat) > 84 || std::abs(lon) > 180) {
      throw Error(path + ": " + p + ": outside the UTM zones (|lat| <= 84)");
    }
    to_utm.emplace(lat, lon, alt);
    if (!options.crs.empty()) {
      throw Error(path + ": the CRS comes from reference_lla (UTM); -a_srs does not apply");
    }
    manifest.crs = to_utm->Crs();
  } else {
    // No geographic reference: the reconstruction's own frame, unless the
    // user says which CRS it is in.
    manifest.crs = options.crs;
  }

  std::vector<PendingImage> pending;
  for (const auto& [name, shot] : rec.at("shots").items()) {
    const std::string p = base + "/shots/" + PointerToken(name);
    if (!shot.is_object()) throw Error(path + ": " + p + ": expected an object");
    const std::string cam = shot.value("camera", std::string());
    if (manifest.FindCamera(cam) < 0) {
      throw Error(path + ": " + p + "/camera: unknown camera id '" + cam + "'");
    }
    const Eigen::Matrix3d R = AxisAngleToRotation(Vector3(shot, "rotation", path, p));
    const Eigen::Vector3d t = Vector3(shot, "translation", path, p);
    const Eigen::Vector3d C = -R.transpose() * t;
    PendingImage image;
    image.name = name;
    image.camera = cam;
    image.position = C;
    image.rotation = CvToPatb(R);
    if (to_utm) {
      image.position = to_utm->Forward(C);
      image.rotation = to_utm->GridRotation(C) * image.rotation;
    }
    image.file = path + ": " + p;  // JSON pointer instead of a line
    image.line = 0;
    pending.push_back(image);
  }

  // Ground: a low percentile of the point heights, below roofs and walls.
  if (!options.ground_height && rec.contains("points") && rec.at("points").is_object() &&
      !rec.at("points").empty()) {
    std::vector<double> h;
    for (const auto& [id, point] : rec.at("points").items()) {
      const Eigen::Vector3d x =
          Vector3(point, "coordinates", path, base + "/points/" + PointerToken(id));
      h.push_back(to_utm ? to_utm->Height(x) : x.z());
    }
    std::sort(h.begin(), h.end());
    const OpenSfmImportOptions defaults;
    const size_t k = static_cast<size_t>(defaults.ground_percentile / 100.0 * (h.size() - 1));
    // Street-level sets see mostly facades: their low percentile lies above
    // the cameras. A ground above a camera contradicts the block, so the
    // ground then stays unknown rather than wrong.
    double lowest_camera = std::numeric_limits<double>::infinity();
    for (const auto& image : pending) lowest_camera = std::min(lowest_camera, image.position.z());
    if (h[k] < lowest_camera) manifest.ground_height = h[k];
  }

  const std::string folder = FolderOf(path);
  std::vector<std::string> folders = ImageFolders(options, folder);
  // OpenSfM keeps images in DATASET/images; ODM in PROJECT/images beside
  // PROJECT/opensfm.
  folders.push_back((fs::path(folder) / "images").string());
  folders.push_back((fs::path(folder) / ".." / "images").string());
  const ImageFinder finder(folders);
  AddImages(pending, finder, options.check_images, &manifest);
  ApplyCommonOptions(options, path, &manifest);
  return manifest;
}

}  // namespace roofsweep::orientation
