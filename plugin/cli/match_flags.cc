#include "plugin/cli/match_flags.h"

namespace roofsweep::cli {

void MatchFlags::Add(ArgParser& p, MatchOptions* o, EdgeOptions* edges) {
  options_ = o;
  edges_ = edges;
  coarse_edges_ = edges->coarse_fusion;
  seed_ = static_cast<int>(o->seed);
  p.Option("-min_length", &o->min_length, "PX", "shortest segment matched (default 15)")
      .Option("-seed", &seed_, "N",
              "seed of matching's random draws: the segments that calibrate the chromatic "
              "thresholds, the subsets of the robust colour estimates (default 1; another seed "
              "shows how much the result depends on them)")
      .Flag("-coarse_edges", &coarse_edges_,
            "also take the edges found at half resolution where no full-resolution segment "
            "lies (hips and valleys broken up by tile courses)")
      .Flag("-match_texture", &match_texture_,
            "also match the segments marked as periodic texture (tile courses, brick rows: "
            "parallel edges of one polarity at a regular spacing on both sides)")
      .Flag("-no_junctions", &no_junctions_,
            "do not complete lines along the epipolar lines from the 3D lines at their ends")
      .Flag("-no_end_check", &no_end_check_,
            "keep a 3D line's ends that no pair of views seeing it across their epipolar lines "
            "holds (one view alone, or views of one strip along it) even when the views that see "
            "them do not confirm them at the line's depth")
      .Flag("-no_junction_ranking", &no_junction_ranking_,
            "rank rival matches of equal support by correlation alone, not first by how many of "
            "their ends meet other 3D lines")
      .Flag("-no_lightness_correlation", &no_lightness_,
            "correlate the flanking regions in a* and b* only, as the paper does (the default "
            "also correlates L*)")
      .Flag("-chromatic_init_best", &init_best_,
            "chromatic thresholds from the best-correlating candidates (keeps more true pairs, ~2x "
            "slower)")
      .Option("-chromatic_factor", &o->threshold_factor, "F",
              "chromatic thresholds = F x median statistic (default 8)")
      .Option("-min_epipolar_angle", &o->min_epipolar_angle, "DEG",
              "a segment meeting a pair's epipolar lines at less than DEG is matched in other "
              "pairs only (default 20; the paper: 40)");
}

void MatchFlags::Apply(const ArgParser& p) const {
  if (seed_ < 0) throw UsageError("-seed must be 0 or more", p.Synopsis());
  options_->seed = static_cast<unsigned>(seed_);
  options_->init_from_best_correlation = init_best_;
  options_->junction_completion = !no_junctions_;
  options_->junction_ranking = !no_junction_ranking_;
  options_->check_ends = !no_end_check_;
  options_->match_texture = match_texture_;
  options_->correlate_lightness = !no_lightness_;
  edges_->coarse_fusion = coarse_edges_;
}

}  // namespace roofsweep::cli
