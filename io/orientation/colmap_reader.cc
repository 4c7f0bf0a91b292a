#include "io/orientation/colmap_reader.h"

#include <cmath>
#include <filesystem>
#include <map>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/orientation/import_common.h"
#include "io/orientation/text_fields.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {
namespace {

bool IsSkipped(const std::string& line) {
  const std::string t = Trim(line);
  return t.empty() || t[0] == '#';
}

std::vector<Camera> ReadCameras(const std::string& path) {
  // model -> number of parameters
  static const std::map<std::string, size_t> kModels = {{"SIMPLE_PINHOLE", 3}, {"PINHOLE", 4},
                                                        {"SIMPLE_RADIAL", 4},  {"RADIAL", 5},
                                                        {"OPENCV", 8},         {"FULL_OPENCV", 12}};
  std::vector<Camera> cameras;
  for (const auto& line : ReadTextLines(path)) {
    if (IsSkipped(line.text)) continue;
    const auto f = SplitWhitespace(line.text);
    if (f.size() < 4) {
      throw Error(AtLine(path, line.number, "expected 'CAMERA_ID MODEL WIDTH HEIGHT PARAMS...'"));
    }
    const auto model = kModels.find(f[1]);
    if (model == kModels.end()) {
      throw Error(AtLine(path, line.number,
                         "camera model '" + f[1] +
                             "' is not supported (SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, "
                             "OPENCV, FULL_OPENCV; undistort other models with COLMAP first)"));
    }
    if (f.size() != 4 + model->second) {
      throw Error(AtLine(path, line.number,
                         f[1] + " needs " + std::to_string(model->second) + " parameters, found " +
                             std::to_string(f.size() - 4)));
    }
    std::vector<double> p;
    for (size_t i = 4; i < f.size(); ++i)
      p.push_back(ParseNumber(f[i], path, line.number, f[1] + " parameter"));
    Camera c;
    c.id = f[0];
    ParseInt(f[0], path, line.number, "CAMERA_ID");
    c.width = ParseInt(f[2], path, line.number, "WIDTH");
    c.height = ParseInt(f[3], path, line.number, "HEIGHT");
    const std::string& m = f[1];
    if (m == "SIMPLE_PINHOLE" || m == "SIMPLE_RADIAL" || m == "RADIAL") {
      c.fx = c.fy = p[0];
      c.cx = p[1];
      c.cy = p[2];
      if (m != "SIMPLE_PINHOLE") c.k1 = p[3];
      if (m == "RADIAL") c.k2 = p[4];
    } else {
      c.fx = p[0];
      c.fy = p[1];
      c.cx = p[2];
      c.cy = p[3];
      if (m == "OPENCV" || m == "FULL_OPENCV") {
        c.k1 = p[4];
        c.k2 = p[5];
        c.p1 = p[6];
        c.p2 = p[7];
      }
      if (m == "FULL_OPENCV") {
        c.k3 = p[8];
        if (p[9] != 0 || p[10] != 0 || p[11] != 0) {
          throw Error(AtLine(path, line.number,
                             "FULL_OPENCV with non-zero k4, k5 or k6 (rational distortion) is "
                             "not supported: roofsweep's camera has k1 k2 k3 p1 p2 only"));
        }
      }
    }
    if (!(c.fx > 0) || !(c.fy > 0)) {
      throw Error(AtLine(path, line.number, "zero or negative focal length"));
    }
    if (c.width <= 0 || c.height <= 0) {
      throw Error(AtLine(path, line.number, "image size must be positive"));
    }
    for (const auto& other : cameras) {
      if (other.id == c.id) throw Error(AtLine(path, line.number, "duplicate camera id " + c.id));
    }
    cameras.push_back(c);
  }
  if (cameras.empty()) throw Error(path + ": no cameras");
  return cameras;
}

std::vector<PendingImage> ReadImages(const std::string& path, const std::vector<Camera>& cameras) {
  std::vector<PendingImage> images;
  const auto lines = ReadTextLines(path);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (IsSkipped(lines[i].text)) continue;
    const auto f = SplitWhitespace(lines[i].text);
    const int n = lines[i].number;
    // The name may hold blanks: everything after CAMERA_ID.
    if (f.size() < 10) {
      throw Error(AtLine(path, n,
                         "expected 'IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME', found " +
                             std::to_string(f.size()) + " fields"));
    }
    ParseInt(f[0], path, n, "IMAGE_ID");
    double v[7];
    const char* what[7] = {"QW", "QX", "QY", "QZ", "TX", "TY", "TZ"};
    for (int k = 0; k < 7; ++k) v[k] = ParseNumber(f[static_cast<size_t>(k + 1)], path, n, what[k]);
    const Eigen::Vector4d q(v[0], v[1], v[2], v[3]);
    if (std::abs(q.norm() - 1.0) > 1e-3) {
      throw Error(AtLine(path, n,
                         "quaternion is not unit length (|q| = " + std::to_string(q.norm()) + ")"));
    }
    ParseInt(f[8], path, n, "CAMERA_ID");
    const std::string camera_id = f[8];
    bool known = false;
    for (const auto& c : cameras) known = known || c.id == camera_id;
    if (!known) throw Error(AtLine(path, n, "unknown camera id " + camera_id));
    // NAME: the rest of the line after the 9th field.
    size_t pos = 0;
    const std::string& text = lines[i].text;
    for (int k = 0; k < 9; ++k) {
      pos = text.find_first_not_of(" \t", pos);
      pos = text.find_first_of(" \t", pos);
    }
    const std::string name = Trim(text.substr(pos));
    const Eigen::Matrix3d R = QuaternionToRotation(v[0], v[1], v[2], v[3]);
    const Eigen::Vector3d t(v[4], v[5], v[6]);
    PendingImage p;
    p.name = name;
    p.camera = camera_id;
    p.position = -R.transpose() * t;
    p.rotation = CvToPatb(R);
    p.file = path;
    p.line = n;
    images.push_back(p);
    // The next line holds the 2D points (possibly empty): skip it whatever it is.
    ++i;
  }
  if (images.empty()) throw Error(path + ": no images");
  return images;
}

}  // namespace

BlockManifest ReadColmap(const std::vector<std::string>& sources, const ImportOptions& options) {
  std::string cameras_txt, images_txt;
  for (const auto& s : sources) {
    std::error_code ec;
    if (fs::is_directory(s, ec)) {
      cameras_txt = (fs::path(s) / "cameras.txt").string();
      images_txt = (fs::path(s) / "images.txt").string();
      if (!fs::is_regular_file(cameras_txt)) {
        const bool binary = fs::is_regular_file(fs::path(s) / "cameras.bin");
        throw Error(s + ": no cameras.txt" +
                    (binary ? " (binary model: convert it with 'colmap model_converter "
                              "--output_type TXT')"
                            : ""));
      }
    } else if (fs::path(s).filename() == "cameras.txt") {
      cameras_txt = s;
    } else if (fs::path(s).filename() == "images.txt") {
      images_txt = s;
    } else {
      throw Error(s + ": expected a COLMAP model folder, cameras.txt or images.txt");
    }
  }
  if (cameras_txt.empty() && !images_txt.empty())
    cameras_txt = (fs::path(FolderOf(images_txt)) / "cameras.txt").string();
  if (images_txt.empty() && !cameras_txt.empty())
    images_txt = (fs::path(FolderOf(cameras_txt)) / "images.txt").string();
  if (cameras_txt.empty()) throw Error("colmap: no model given");

  BlockManifest manifest;
  manifest.cameras = ReadCameras(cameras_txt);
  const auto pending = ReadImages(images_txt, manifest.cameras);
  manifest.crs = options.crs;
  const std::string folder = FolderOf(images_txt);
  std::vector<std::string> folders = ImageFolders(options, folder);
  folders.push_back((fs::path(folder) / ".." / "images").string());
  folders.push_back((fs::path(folder) / ".." / ".." / "images").string());
  AddImages(pending, ImageFinder(folders), options.check_images, &manifest);
  ApplyCommonOptions(options, images_txt, &manifest);
  return manifest;
}

}  // namespace roofsweep::orientation
