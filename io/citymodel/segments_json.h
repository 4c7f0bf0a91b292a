#pragma once

#include <string>
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
};

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

}  // namespace roofsweep
