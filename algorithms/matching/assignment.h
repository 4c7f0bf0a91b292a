#pragma once

#include <utility>
#include <vector>

namespace roofsweep {

// One hypothesis for the one-to-one assignment: the (view, segment) keys it
// would use and its score (higher is better).
struct AssignmentItem {
  std::vector<std::pair<int, int>> keys;  // keys[0], keys[1]: the matched pair
  double score = 0;
};

// One-to-one, bidirectional matching as a global greedy assignment: items in
// decreasing score (ties: input order), an item is taken when none of its
// first two keys (the stereo pair) is taken yet; its further keys (support
// in other views) are taken along where still free. Equivalent in effect to
// the mutual-best rule of ATOMI's bidirectional relaxation for a
// score-ranked pool, deterministic, O(n log n). Returns, per item, the keys
// it got (empty when rejected).
std::vector<std::vector<std::pair<int, int>>> AssignOneToOne(
    const std::vector<AssignmentItem>& items);

}  // namespace roofsweep
