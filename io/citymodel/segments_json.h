#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/geometry/segment3.h"

namespace roofsweep {

// A 3D segment with what it is: the simulator's ground-truth edges (kind
// "ridge", "eave", "ground_marking", ...; building index or -1) and, later,
// reconstructed 3D lines.
struct LabelledSegment {
  Segment3 segment;
  std::string kind;
  int building = -1;
  // Reprojection residual of a 3D line matched by stereo in three views or
  // more (field rms_px of the lines3d layer roofsweep writes); NaN when the
  // source gives none or says it measures nothing: a line from two views
  // (fields views) or completed from its junctions (depth_from other than
  // "stereo") reprojects exactly by construction.
  double rms_px = std::numeric_limits<double>::quiet_NaN();
  // Where a matched line was observed: (image name, segment id) from the
  // field observations ("name:id name:id ...") of the lines3d layer
  // `roofsweep match` writes, id -1 where unknown; empty when the source
  // has none or a token does not parse.
  std::vector<std::pair<std::string, int>> observations;
};

// The field observations of the lines3d layer: "name:id name:id ...",
// image name and segment id; id -1 where the segment is not known (lines
// matched in a tile's image windows, whose segments are not those of the
// whole image). Parse gives empty when any token does not parse (an image
// name with a space cannot be told apart).
std::string FormatObservations(const std::vector<std::pair<std::string, int>>& observations);
std::vector<std::pair<std::string, int>> ParseObservations(const std::string& text);

struct SegmentSet {
  std::string crs;  // empty: local frame
  std::vector<LabelledSegment> segments;
};

// A small JSON document: {"type": "roofsweep_segments", "crs": ...,
// "segments": [{"a": [x, y, z], "b": [x, y, z], "kind": "...", "building": n}]}.
// Atomic write; an existing file needs overwrite.
void WriteSegmentsJson(const SegmentSet& set, const std::string& path, bool overwrite);
// Errors name the file and the JSON pointer of the bad entry.
SegmentSet ReadSegmentsJson(const std::string& path);

// Reads 3D segments from a segments JSON document or, for anything else, an
// OGR dataset: the layer `layer` (default: "lines3d", else the first layer
// with line geometry); every LineString part becomes segments between its
// consecutive vertices, `kind` from a "kind" field when present.
SegmentSet ReadSegments(const std::string& path, const std::string& layer = {});

}  // namespace roofsweep
