#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "algorithms/eval/evaluate.h"
#include "algorithms/eval/lod1_eval.h"

namespace roofsweep {

// A fixed-width text table of the figures and counts, for a terminal or a
// log. Undefined ratios print as "n/a".
std::string FormatTable(const EvalResult& result);

// The figures as JSON: fractions 0..1, angles in degrees, lengths in metres,
// undefined ratios null. Keys: roof_planes.{completeness, correctness,
// quality, n_reference, n_result, tp_reference, tp_result, n_1_to_m, n_n_to_1,
// n_n_to_m}, geometry.{angle_median_deg, angle_rms_deg, angle_max_deg,
// vertex_rms_m, vertex_rms_gsd, vertex_median_m, vertex_within_2gsd,
// vertex_places.{on_outline, inside, over_another_roof, over_no_roof}.{count,
// sum_squares_m2}, rmsz_m,
// dz_mean_m, matched_pairs, ...},
// buildings.{completeness, correctness, quality, roof_type_agreement, ...},
// lines3d.{evaluated, precision, completeness, roof_edge_completeness, ...},
// input.{result, reference}, options.
nlohmann::json ToJson(const EvalResult& result);

// The LoD1 blocks' section of the table, and its JSON (blocks,
// over_reference, found, found_by_block_only, found_fraction, n_reference,
// cells, rmsz_m, dz_mean_m, rmsz_at_mean_m).
std::string FormatLod1Table(const Lod1Scores& scores);
nlohmann::json Lod1ToJson(const Lod1Scores& scores);

}  // namespace roofsweep
