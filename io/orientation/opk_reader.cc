#include "io/orientation/opk_reader.h"

#include <Eigen/Dense>
#include <filesystem>
#include <map>
#include <set>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/orientation/camera_file_reader.h"
#include "io/orientation/import_common.h"
#include "io/orientation/text_fields.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {
namespace {

// Largest difference accepted between Metashape's r matrix and the one
// recomputed from its OPK: both are printed with ~6 decimals.
constexpr double kMatrixTolerance = 1e-4;

std::vector<std::string> SplitRecord(const std::string& line) {
  if (line.find('\t') != std::string::npos) return SplitDelimited(line, '\t');
  bool quoted = false;
  char q = 0;
  for (char c : line) {
    if (quoted) {
      if (c == q) quoted = false;
    } else if (c == '"' || c == '\'') {
      quoted = true;
      q = c;
    } else if (c == ',') {
      return SplitDelimited(line, ',');
    }
  }
  return SplitWhitespace(line);
}

struct Columns {
  int name = -1, x = -1, y = -1, z = -1, omega = -1, phi = -1, kappa = -1, camera = -1;
  int r11 = -1;  // Metashape: r11..r33 follow in order
  size_t count = 0;
};

Columns MapHeader(const std::vector<std::string>& fields, const std::string& file, int line) {
  static const std::map<std::string, int Columns::*> kNames = {{"imagename", &Columns::name},
                                                               {"filename", &Columns::name},
                                                               {"image", &Columns::name},
                                                               {"name", &Columns::name},
                                                               {"photoid", &Columns::name},
                                                               {"label", &Columns::name},
                                                               {"x", &Columns::x},
                                                               {"easting", &Columns::x},
                                                               {"y", &Columns::y},
                                                               {"northing", &Columns::y},
                                                               {"z", &Columns::z},
                                                               {"altitude", &Columns::z},
                                                               {"height", &Columns::z},
                                                               {"omega", &Columns::omega},
                                                               {"phi", &Columns::phi},
                                                               {"kappa", &Columns::kappa},
                                                               {"camera", &Columns::camera},
                                                               {"r11", &Columns::r11}};
  Columns c;
  c.count = fields.size();
  for (size_t i = 0; i < fields.size(); ++i) {
    std::string key = Lower(Trim(fields[i]));
    if (!key.empty() && key[0] == '#') key = Trim(key.substr(1));
    const auto it = kNames.find(key);
    if (it == kNames.end()) continue;
    if (c.*(it->second) >= 0) {
      throw Error(AtLine(file, line, "header names column '" + key + "' twice"));
    }
    c.*(it->second) = static_cast<int>(i);
  }
  const std::pair<const char*, int> required[] = {
      {"image name", c.name}, {"x", c.x},     {"y", c.y},        {"z", c.z},
      {"omega", c.omega},     {"phi", c.phi}, {"kappa", c.kappa}};
  for (const auto& [what, index] : required) {
    if (index < 0) {
      std::string hint;
      for (const auto& f : fields) {
        const std::string l = Lower(f);
        if (l == "roll" || l == "pitch" || l == "yaw" || l == "latitude")
          hint =
              " (roll/pitch/yaw and lat/lon are not orientations roofsweep imports; export "
              "omega/phi/kappa in a projected CRS)";
      }
      throw Error(AtLine(file, line, "header has no '" + std::string(what) + "' column" + hint));
    }
  }
  if (c.r11 >= 0 && static_cast<size_t>(c.r11 + 9) > c.count) {
    throw Error(AtLine(file, line, "header has r11 but not the 8 matrix columns after it"));
  }
  return c;
}

bool AllNumeric(const std::vector<std::string>& fields, size_t from) {
  for (size_t i = from; i < fields.size(); ++i) {
    char* end = nullptr;
    const std::string t = Trim(fields[i]);
    std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size()) return false;
  }
  return true;
}

// Interior orientation found without being asked for: Pix4D writes the
// calibrated_camera_parameters.txt (and the .cam) beside the external file.
std::string Pix4dCameraFileBeside(const std::string& opk) {
  const std::string name = fs::path(opk).filename().string();
  const std::string suffix = "calibrated_external_camera_parameters.txt";
  if (!EndsWith(name, suffix)) return "";
  const std::string prefix = name.substr(0, name.size() - suffix.size());
  const fs::path folder = FolderOf(opk);
  for (const std::string& candidate :
       {prefix + "calibrated_camera_parameters.txt",
        prefix + "pix4d_calibrated_internal_camera_parameters.cam"}) {
    if (fs::is_regular_file(folder / candidate)) return (folder / candidate).string();
  }
  return "";
}

}  // namespace

BlockManifest ReadOpk(const std::vector<std::string>& sources, const ImportOptions& options) {
  std::string opk, camera_file = options.camera_file;
  for (const auto& s : sources) {
    const std::string ext = Lower(fs::path(s).extension().string());
    if (ext == ".xml" || ext == ".yaml" || ext == ".yml" || ext == ".cam") {
      camera_file = s;
    } else if (opk.empty()) {
      opk = s;
    } else {
      throw Error(s + ": one OPK file per import (plus a camera file)");
    }
  }
  if (opk.empty()) throw Error("opk: no orientation file given");
  if (camera_file.empty()) camera_file = Pix4dCameraFileBeside(opk);
  if (camera_file.empty()) {
    throw Error(opk +
                ": OPK files carry no interior orientation; give a camera file (orthority "
                ".yaml, Pix4D .cam or calibrated_camera_parameters.txt, Metashape .xml, "
                "OpenSfM .json or a roofsweep manifest)");
  }
  const CameraSet cameras = ReadCameraFile(camera_file);

  const std::vector<TextLine> lines = ReadTextLines(opk);
  std::optional<Columns> columns;
  std::vector<PendingImage> pending;
  int header_line = 0;
  for (const auto& line : lines) {
    const std::string t = Trim(line.text);
    if (t.empty()) continue;
    if (t[0] == '#') {
      // Metashape puts its header in a comment: "# PhotoID, X, Y, Z, ...".
      if (!columns && Lower(t).find("photoid") != std::string::npos) {
        columns = MapHeader(SplitRecord(Trim(t.substr(1))), opk, line.number);
        header_line = line.number;
      }
      continue;
    }
    const std::vector<std::string> fields = SplitRecord(t);
    if (!columns) {
      if (fields.size() == 7 && AllNumeric(fields, 1)) {
        // Headerless: name X Y Z omega phi kappa.
        Columns c;
        c.name = 0, c.x = 1, c.y = 2, c.z = 3, c.omega = 4, c.phi = 5, c.kappa = 6;
        c.count = 7;
        columns = c;
      } else {
        columns = MapHeader(fields, opk, line.number);
        header_line = line.number;
        continue;
      }
    }
    const Columns& c = *columns;
    if (fields.size() != c.count) {
      throw Error(AtLine(opk, line.number,
                         "wrong column count: expected " + std::to_string(c.count) + " (" +
                             (header_line ? "as the header on line " + std::to_string(header_line)
                                          : std::string("name X Y Z omega phi kappa")) +
                             "), found " + std::to_string(fields.size())));
    }
    auto num = [&](int index, const char* what) {
      return ParseNumber(fields[static_cast<size_t>(index)], opk, line.number, what);
    };
    PendingImage p;
    p.file = opk;
    p.line = line.number;
    p.name = Trim(fields[static_cast<size_t>(c.name)]);
    p.position = {num(c.x, "X"), num(c.y, "Y"), num(c.z, "Z")};
    const double omega = num(c.omega, "omega"), phi = num(c.phi, "phi"),
                 kappa = num(c.kappa, "kappa");
    p.rotation = OpkToRotation(omega, phi, kappa);
    if (c.r11 >= 0) {
      Eigen::Matrix3d m;
      for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = num(c.r11 + k, "rotation matrix");
      const double direct = (m - p.rotation).cwiseAbs().maxCoeff();
      const double transposed = (m.transpose() - p.rotation).cwiseAbs().maxCoeff();
      if (std::min(direct, transposed) > kMatrixTolerance) {
        throw Error(AtLine(opk, line.number,
                           "the r11..r33 matrix is neither R(omega, phi, kappa) nor its "
                           "transpose (differs by " +
                               std::to_string(std::min(direct, transposed)) + ")"));
      }
    }
    const std::string column = c.camera >= 0 ? Trim(fields[static_cast<size_t>(c.camera)]) : "";
    const Camera* camera = cameras.Find(column, p.name);
    if (!camera) {
      throw Error(AtLine(opk, line.number,
                         (column.empty() ? "no camera for image '" + p.name + "'"
                                         : "unknown camera id '" + column + "'") +
                             " in " + camera_file + " (it has " +
                             std::to_string(cameras.cameras.size()) + " cameras)"));
    }
    p.camera = camera->id;
    pending.push_back(p);
  }
  if (pending.empty()) throw Error(opk + ": no images");

  BlockManifest manifest;
  std::set<std::string> used;
  for (const auto& p : pending) used.insert(p.camera);
  for (const auto& cam : cameras.cameras)
    if (used.count(cam.id)) manifest.cameras.push_back(cam);
  manifest.crs = ResolveCrs(options, {ReplaceExtension(opk, ".prj")});
  const ImageFinder finder(ImageFolders(options, FolderOf(opk)));
  AddImages(pending, finder, options.check_images, &manifest);
  ScaleMmCameras(cameras, &manifest);
  ApplyCommonOptions(options, opk, &manifest);
  return manifest;
}

}  // namespace roofsweep::orientation
