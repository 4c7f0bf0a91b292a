#pragma once

#include <vector>

#include "algorithms/edges/edge_options.h"
#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// One flag per segment: true where it lies inside a periodic pattern of
// parallel edges of its own polarity (the texture_* options of
// EdgeOptions say what counts).
std::vector<bool> MarkRepetitiveTexture(const Segments2D& segments, const EdgeOptions& options);

}  // namespace roofsweep
