#include "io/orientation/camera_file_reader.h"

#include <filesystem>

#include "algorithms/core/error.h"
#include "io/orientation/opensfm_reader.h"
#include "io/orientation/pix4d_reader.h"
#include "io/orientation/text_fields.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {
namespace {

std::string CameraKey(const std::string& id) {
  std::string k = Lower(Trim(id));
  if (StartsWith(k, "v2 ")) k = k.substr(3);  // OpenSfM/ODM camera ids carry a version prefix
  return k;
}

// Pix4D *_pix4d_calibrated_internal_camera_parameters.cam: "KEY value" lines;
// the sensor size in mm only appears in the comment
// "#Focal Length mm assuming a sensor width of 12.8x8.53mm".
CameraSet ReadPix4dCam(const std::string& path) {
  std::map<std::string, double> v;
  double sensor_w = 0, sensor_h = 0;
  int focal_line = 0;
  for (const auto& line : ReadTextLines(path)) {
    const std::string t = Trim(line.text);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string key = "sensor width of ";
      const size_t p = t.find(key);
      if (p != std::string::npos) {
        std::string dims = t.substr(p + key.size());
        if (EndsWith(dims, "mm")) dims = dims.substr(0, dims.size() - 2);
        const size_t x = dims.find('x');
        if (x == std::string::npos)
          throw Error(AtLine(path, line.number, "cannot read the sensor size"));
        sensor_w = ParseNumber(dims.substr(0, x), path, line.number, "sensor width");
        sensor_h = ParseNumber(dims.substr(x + 1), path, line.number, "sensor height");
      }
      continue;
    }
    const auto tokens = SplitWhitespace(t);
    if (tokens.size() == 2) {
      v[tokens[0]] = ParseNumber(tokens[1], path, line.number, tokens[0]);
      if (tokens[0] == "F") focal_line = line.number;
    } else if (!StartsWith(t, "Pix4D")) {
      throw Error(AtLine(path, line.number, "expected 'KEY VALUE', found '" + t + "'"));
    }
  }
  for (const char* key : {"F", "Px", "Py"}) {
    if (!v.count(key)) throw Error(path + ": missing " + std::string(key));
  }
  if (!(sensor_w > 0) || !(sensor_h > 0)) {
    throw Error(path + ": no '#Focal Length mm assuming a sensor width of WxHmm' line");
  }
  if (!(v["F"] > 0)) throw Error(AtLine(path, focal_line, "zero or negative focal length"));
  CameraSet set;
  Camera c;
  c.id = fs::path(path).stem().string();
  c.fx = c.fy = v["F"];
  // Px, Py: mm from the top-left corner of the sensor, y down (Pix4D's K
  // has cx = Px * w_px / W_mm).
  c.cx = v["Px"];
  c.cy = v["Py"];
  c.k1 = v.count("K1") ? v["K1"] : 0;
  c.k2 = v.count("K2") ? v["K2"] : 0;
  c.k3 = v.count("K3") ? v["K3"] : 0;
  c.p1 = v.count("T1") ? v["T1"] : 0;
  c.p2 = v.count("T2") ? v["T2"] : 0;
  set.cameras.push_back(c);
  set.in_mm[c.id] = {sensor_w, sensor_h};
  return set;
}

}  // namespace

const Camera* CameraSet::Find(const std::string& camera_column,
                              const std::string& image_name) const {
  if (!camera_column.empty()) {
    for (const auto& c : cameras)
      if (c.id == camera_column) return &c;
    for (const auto& c : cameras)
      if (CameraKey(c.id) == CameraKey(camera_column)) return &c;
    return nullptr;
  }
  if (!image_camera.empty()) {
    auto it = image_camera.find(image_name);
    if (it == image_camera.end()) {
      // The OPK file may drop the extension the calibration file keeps.
      for (auto j = image_camera.begin(); j != image_camera.end(); ++j) {
        if (fs::path(j->first).stem().string() == fs::path(image_name).stem().string() ||
            fs::path(j->first).stem().string() == image_name) {
          it = j;
          break;
        }
      }
    }
    if (it != image_camera.end()) {
      for (const auto& c : cameras)
        if (c.id == it->second) return &c;
    }
    return nullptr;
  }
  if (cameras.size() == 1) return &cameras.front();
  return nullptr;
}

CameraSet ReadCameraFile(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Error(path + ": camera file does not exist");
  const std::string ext = Lower(fs::path(path).extension().string());
  CameraSet set;
  if (ext == ".yaml" || ext == ".yml") {
    set.cameras = ReadOrthorityYaml(path);
  } else if (ext == ".cam") {
    set = ReadPix4dCam(path);
  } else if (ext == ".xml") {
    set.cameras = ReadMetashapeCalibration(path);
  } else if (ext == ".json") {
    const std::string text = Trim(ReadTextFile(path));
    const bool manifest = !text.empty() && text[0] == '{' &&
                          text.find("\"images\"") != std::string::npos &&
                          text.find("\"projection_type\"") == std::string::npos;
    if (manifest) {
      set.cameras = ReadManifest(path).cameras;
    } else {
      set.cameras = ReadOpenSfmCameras(path);
    }
  } else if (ext == ".txt") {
    Pix4dCameras(ParsePix4dCalibrated(path), &set.cameras, &set.image_camera);
  } else {
    throw Error(path +
                ": unknown camera file type (expected .yaml orthority, .cam/.txt Pix4D, .xml "
                "Metashape, .json OpenSfM or roofsweep manifest)");
  }
  set.source = path;
  if (set.cameras.empty()) throw Error(path + ": no cameras found");
  for (const auto& c : set.cameras) {
    if (!set.in_mm.count(c.id)) c.Validate(path);
  }
  return set;
}

void ScaleMmCameras(const CameraSet& set, BlockManifest* manifest) {
  for (auto& c : manifest->cameras) {
    const auto it = set.in_mm.find(c.id);
    if (it == set.in_mm.end()) continue;
    const double sx = c.width / it->second.width_mm;
    const double sy = c.height / it->second.height_mm;
    c.fx *= sx;
    c.fy *= sy;
    c.cx *= sx;
    c.cy *= sy;
    c.pixel_size_mm = it->second.width_mm / c.width;
  }
}

}  // namespace roofsweep::orientation
