#pragma once

#include "algorithms/edges/edge_options.h"
#include "algorithms/matching/match_options.h"
#include "plugin/cli/arg_parser.h"

namespace roofsweep::cli {

// The matching options (and the edge options that only matching's input
// needs) that `match`, `run` and `sweep` share, declared once so that their
// names, help and checks cannot drift apart. Add() binds them to the parser;
// Apply(), right after ArgParser::Parse, turns the flags into MatchOptions
// and EdgeOptions and throws UsageError for values out of range.
class MatchFlags {
 public:
  void Add(ArgParser& p, MatchOptions* options, EdgeOptions* edges);
  void Apply(const ArgParser& p) const;

 private:
  MatchOptions* options_ = nullptr;
  EdgeOptions* edges_ = nullptr;
  bool coarse_edges_ = false;
  bool init_best_ = false, no_junctions_ = false, no_junction_ranking_ = false,
       no_end_check_ = false, match_texture_ = false, no_lightness_ = false;
  int seed_ = 0;
};

}  // namespace roofsweep::cli
