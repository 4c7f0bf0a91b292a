#pragma once

#include <string>
#include <vector>

#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/segment3.h"

namespace roofsweep::orientation {

// The line annotations of an Oxford VGG multi-view set (2D/*.lines,
// *nview-lines, 3D/*l3d): the ground truth of line matching on real
// images.
struct VggLineAnnotations {
  // View stems ("001", "house.000"), in the order of the nview columns
  // (the sorted .lines files).
  std::vector<std::string> views;
  std::vector<Segments2D> lines;  // per view; pixel-corner coordinates (VGG's + 0.5 px)
  // Per annotated 3D line: its line id in each view, -1 where unmarked ("*"
  // or "-1" in the file).
  std::vector<std::vector<int>> rows;
  // Per row, when the set has an l3d file; in the world `ReadVgg` imports
  // (z mirrored for the left-handed sets).
  std::vector<Segment3> lines3d;
};

// Reads the annotations below `folder`. Throws roofsweep::Error naming the
// file and line on malformed rows, ids out of range or a row count of l3d
// that differs from nview-lines; and when the folder has no .lines or no
// nview-lines file.
VggLineAnnotations ReadVggLineAnnotations(const std::string& folder);

}  // namespace roofsweep::orientation
