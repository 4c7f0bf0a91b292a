#pragma once

#include "algorithms/matching/match_options.h"
#include "plugin/cli/arg_parser.h"

namespace roofsweep::cli {

// The matching options that `match`, `run` and `sweep` share, declared once
// so that their names, help and checks cannot drift apart. Add() binds them
// to the parser; Apply(), right after ArgParser::Parse, turns the flags into
// MatchOptions and throws UsageError for values out of range.
class MatchFlags {
 public:
  void Add(ArgParser& p, MatchOptions* options);
  void Apply(const ArgParser& p) const;

 private:
  MatchOptions* options_ = nullptr;
  bool init_best_ = false, no_junctions_ = false, no_junction_ranking_ = false,
       match_texture_ = false;
  int seed_ = 0;
};

}  // namespace roofsweep::cli
