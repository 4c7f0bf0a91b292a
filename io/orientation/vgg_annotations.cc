#include "io/orientation/vgg_annotations.h"

#include <filesystem>

#include "algorithms/core/error.h"
#include "io/orientation/text_fields.h"
#include "io/orientation/vgg_reader.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {

VggLineAnnotations ReadVggLineAnnotations(const std::string& folder) {
  VggLineAnnotations a;
  const auto line_files = VggFilesEndingWith(folder, ".lines");
  if (line_files.empty()) throw Error(folder + ": no *.lines annotation files below it");
  for (const std::string& path : line_files) {
    a.views.push_back(fs::path(path).stem().string());
    Segments2D segs;
    for (const TextLine& l : ReadTextLines(path)) {
      if (Trim(l.text).empty()) continue;
      // Model House appends two more columns ("x0 y0 x1 y1 blah blah").
      const auto t = SplitWhitespace(l.text);
      if (t.size() < 4)
        throw Error(AtLine(
            path, l.number,
            "line segment x0 y0 x1 y1: expected 4 numbers, found " + std::to_string(t.size())));
      double v[4];
      for (int k = 0; k < 4; ++k) v[k] = ParseNumber(t[k], path, l.number, "line segment");
      Segment2D s;
      // VGG's origin is the centre of the top-left pixel.
      s.p0 = {v[0] + 0.5, v[1] + 0.5};
      s.p1 = {v[2] + 0.5, v[3] + 0.5};
      segs.push_back(s);
    }
    a.lines.push_back(std::move(segs));
  }
  const auto nview = VggFilesEndingWith(folder, "nview-lines");
  if (nview.empty()) throw Error(folder + ": no nview-lines file below it");
  const std::string& npath = nview.front();
  for (const TextLine& l : ReadTextLines(npath)) {
    const auto t = SplitWhitespace(l.text);
    if (t.empty()) continue;
    if (t.size() != a.views.size())
      throw Error(AtLine(npath, l.number,
                         std::to_string(t.size()) + " columns for " +
                             std::to_string(a.views.size()) + " views (.lines files)"));
    std::vector<int> row;
    for (size_t v = 0; v < t.size(); ++v) {
      const int id = t[v] == "*" ? -1 : ParseInt(t[v], npath, l.number, "line id");
      if (id < -1 || id >= static_cast<int>(a.lines[v].size()))
        throw Error(AtLine(npath, l.number,
                           "line id " + t[v] + " out of range for " + a.views[v] + ".lines (" +
                               std::to_string(a.lines[v].size()) + " lines)"));
      row.push_back(id);
    }
    a.rows.push_back(std::move(row));
  }
  const auto l3d = VggFilesEndingWith(folder, "l3d");
  if (!l3d.empty()) {
    const std::string& path = l3d.front();
    const double z = VggWorldIsMirrored(folder) ? -1 : 1;
    for (const TextLine& l : ReadTextLines(path)) {
      if (Trim(l.text).empty()) continue;
      const auto v = ParseNumbers(l, path, 6, "3D line X0 Y0 Z0 X1 Y1 Z1");
      a.lines3d.push_back({{v[0], v[1], z * v[2]}, {v[3], v[4], z * v[5]}});
    }
    if (a.lines3d.size() != a.rows.size())
      throw Error(path + ": " + std::to_string(a.lines3d.size()) + " 3D lines for " +
                  std::to_string(a.rows.size()) + " rows of " + npath);
  }
  return a;
}

}  // namespace roofsweep::orientation
