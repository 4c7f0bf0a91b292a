#include "io/orientation/pix4d_reader.h"

#include <Eigen/Dense>
#include <filesystem>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/orientation/import_common.h"
#include "io/orientation/text_fields.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {
namespace {

bool IsBlockStart(const std::vector<std::string>& tokens) {
  if (tokens.size() < 3) return false;
  for (size_t i = tokens.size() - 2; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos) return false;
  }
  return true;
}

std::string JoinName(const std::vector<std::string>& tokens) {
  std::string name;
  for (size_t i = 0; i + 2 < tokens.size(); ++i) name += (i ? " " : "") + tokens[i];
  return name;
}

// Pix4D's offset file: one line "X Y Z".
Eigen::Vector3d ReadOffset(const std::string& path) {
  for (const auto& line : ReadTextLines(path)) {
    if (Trim(line.text).empty()) continue;
    const auto v = ParseNumbers(line, path, 3, "offset");
    return {v[0], v[1], v[2]};
  }
  throw Error(path + ": empty offset file");
}

std::string FindOffsetBeside(const std::string& ccp) {
  const std::string name = fs::path(ccp).filename().string();
  const std::string suffix = "calibrated_camera_parameters.txt";
  const std::string folder = FolderOf(ccp);
  if (EndsWith(name, suffix)) {
    const std::string candidate =
        (fs::path(folder) / (name.substr(0, name.size() - suffix.size()) + "offset.xyz")).string();
    if (fs::is_regular_file(candidate)) return candidate;
  }
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    if (EndsWith(it->path().filename().string(), "_offset.xyz")) found.push_back(it->path());
  }
  if (found.size() == 1) return found.front();
  return "";
}

}  // namespace

std::vector<Pix4dCalibratedImage> ParsePix4dCalibrated(const std::string& path) {
  const std::vector<TextLine> all = ReadTextLines(path);
  std::vector<TextLine> lines;
  for (const auto& l : all)
    if (!Trim(l.text).empty()) lines.push_back(l);
  size_t i = 0;
  while (i < lines.size() && !IsBlockStart(SplitWhitespace(lines[i].text))) ++i;
  if (i == lines.size()) throw Error(path + ": no camera block (NAME WIDTH HEIGHT) found");
  std::vector<Pix4dCalibratedImage> out;
  while (i < lines.size()) {
    const auto tokens = SplitWhitespace(lines[i].text);
    if (!IsBlockStart(tokens)) {
      throw Error(AtLine(path, lines[i].number,
                         "expected 'NAME WIDTH HEIGHT', found '" + Trim(lines[i].text) + "'"));
    }
    if (i + 10 > lines.size()) {
      throw Error(AtLine(path, lines[i].number, "truncated camera block (needs 10 lines)"));
    }
    Pix4dCalibratedImage b;
    b.name = JoinName(tokens);
    b.line = lines[i].number;
    b.width = ParseInt(tokens[tokens.size() - 2], path, b.line, "image width");
    b.height = ParseInt(tokens[tokens.size() - 1], path, b.line, "image height");
    for (int r = 0; r < 3; ++r) {
      const auto v = ParseNumbers(lines[i + 1 + r], path, 3, "camera matrix K");
      for (int c = 0; c < 3; ++c) b.K(r, c) = v[c];
    }
    const auto rad = ParseNumbers(lines[i + 4], path, 3, "radial distortion");
    b.radial = {rad[0], rad[1], rad[2]};
    const auto tan = ParseNumbers(lines[i + 5], path, 2, "tangential distortion");
    b.tangential = {tan[0], tan[1]};
    const auto t = ParseNumbers(lines[i + 6], path, 3, "camera position t");
    b.t = {t[0], t[1], t[2]};
    for (int r = 0; r < 3; ++r) {
      const auto v = ParseNumbers(lines[i + 7 + r], path, 3, "camera rotation R");
      for (int c = 0; c < 3; ++c) b.R(r, c) = v[c];
    }
    if (!(b.K(0, 0) > 0) || !(b.K(1, 1) > 0)) {
      throw Error(AtLine(path, lines[i + 1].number, "zero or negative focal length"));
    }
    if ((b.R * b.R.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 ||
        b.R.determinant() < 0) {
      throw Error(AtLine(path, lines[i + 7].number, "camera rotation R is not a rotation matrix"));
    }
    out.push_back(b);
    i += 10;
  }
  return out;
}

void Pix4dCameras(const std::vector<Pix4dCalibratedImage>& blocks, std::vector<Camera>* cameras,
                  std::map<std::string, std::string>* image_camera) {
  for (const auto& b : blocks) {
    Camera c;
    c.width = b.width;
    c.height = b.height;
    c.fx = b.K(0, 0);
    c.fy = b.K(1, 1);
    c.skew = b.K(0, 1);
    c.cx = b.K(0, 2);  // Pix4D already uses the corner origin
    c.cy = b.K(1, 2);
    c.k1 = b.radial[0];
    c.k2 = b.radial[1];
    c.k3 = b.radial[2];
    c.p1 = b.tangential[0];
    c.p2 = b.tangential[1];
    std::string id;
    for (const auto& existing : *cameras) {
      if (existing.width == c.width && existing.height == c.height && existing.fx == c.fx &&
          existing.fy == c.fy && existing.skew == c.skew && existing.cx == c.cx &&
          existing.cy == c.cy && existing.k1 == c.k1 && existing.k2 == c.k2 &&
          existing.k3 == c.k3 && existing.p1 == c.p1 && existing.p2 == c.p2) {
        id = existing.id;
        break;
      }
    }
    if (id.empty()) {
      c.id = "pix4d_" + std::to_string(cameras->size() + 1);
      id = c.id;
      cameras->push_back(c);
    }
    (*image_camera)[b.name] = id;
  }
}

BlockManifest ReadPix4d(const std::vector<std::string>& sources, const ImportOptions& options) {
  std::string ccp, offset_file;
  for (const auto& s : sources) {
    if (EndsWith(Lower(s), ".xyz"))
      offset_file = s;
    else if (ccp.empty())
      ccp = s;
    else
      throw Error(s + ": pix4d takes one calibrated_camera_parameters.txt (and an offset.xyz)");
  }
  if (ccp.empty()) throw Error("pix4d: no calibrated_camera_parameters.txt given");
  if (offset_file.empty()) offset_file = FindOffsetBeside(ccp);
  if (offset_file.empty()) {
    throw Error(ccp +
                ": no *_offset.xyz beside it (Pix4D positions are relative to it); pass the "
                "offset file as a second source");
  }
  const Eigen::Vector3d offset = ReadOffset(offset_file);
  const auto blocks = ParsePix4dCalibrated(ccp);

  BlockManifest manifest;
  std::map<std::string, std::string> image_camera;
  Pix4dCameras(blocks, &manifest.cameras, &image_camera);
  std::vector<PendingImage> pending;
  for (const auto& b : blocks) {
    PendingImage p;
    p.name = b.name;
    p.camera = image_camera.at(b.name);
    p.position = b.t + offset;
    p.rotation = CvToPatb(b.R);
    p.file = ccp;
    p.line = b.line;
    pending.push_back(p);
  }
  std::vector<std::string> crs_candidates;
  const std::string name = fs::path(ccp).filename().string();
  const std::string suffix = "calibrated_camera_parameters.txt";
  if (EndsWith(name, suffix)) {
    crs_candidates.push_back(
        (fs::path(FolderOf(ccp)) / (name.substr(0, name.size() - suffix.size()) + "wkt.prj"))
            .string());
  }
  manifest.crs = ResolveCrs(options, crs_candidates);
  const ImageFinder finder(ImageFolders(options, FolderOf(ccp)));
  AddImages(pending, finder, options.check_images, &manifest);
  ApplyCommonOptions(options, ccp, &manifest);
  return manifest;
}

}  // namespace roofsweep::orientation
