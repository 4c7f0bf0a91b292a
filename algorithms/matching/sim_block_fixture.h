#pragma once

// A small simulated block (2 strips x 3 views of 512 px) with its true
// edges, shared by the matching tests and benchmark.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"

namespace roofsweep {

struct SimBlock {
  Block block;
  std::vector<cv::Mat> images;  // CV_32FC3 RGB
  std::vector<Segment3> truth, roof, extra;
};

SimBlock SimulateSmallBlock(uint64_t seed);

}  // namespace roofsweep
