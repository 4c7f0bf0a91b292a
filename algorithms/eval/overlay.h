#pragma once

#include <opencv2/core.hpp>

#include "algorithms/buildings/city_model.h"
#include "algorithms/eval/evaluate.h"

namespace roofsweep {

struct OverlayOptions {
  double metres_per_pixel = 0.1;  // raised automatically so no side exceeds max_side_px
  int max_side_px = 8000;
  double margin_m = 5.0;  // around the union of both models' extents
};

// A plan view (north up) for a person to look at: reference roof planes
// filled (green: matched, red: missed) with blue outlines; result roof
// planes outlined (dark green: correct, magenta: false); below the map a
// legend with the headline figures and a scale bar. LoD1 blocks (`blocks`,
// scored apart from the LoD2 result; may be null) are outlined in orange
// by their footprints, and the legend then says so. BGR, 8 bit; the map's
// top-left pixel corner is at (min x - margin, max y + margin) or so that
// the map is at least as wide as the legend. `eval` must come from
// Evaluate(result, truth, eval.options); Error otherwise.
cv::Mat RenderOverlay(const CityModel& result, const CityModel& truth, const EvalResult& eval,
                      const OverlayOptions& options = {}, const CityModel* blocks = nullptr);

}  // namespace roofsweep
