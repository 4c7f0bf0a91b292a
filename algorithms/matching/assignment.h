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

// Uniqueness before the assignment: false for an item when another item
// matches one of its two segments to a different 3D line and scores at least
// as high. Two items describe the same line when the other's partner segment
// is among this one's keys (its pair or its support in other views), or the
// other way round: the verification's own notion of consistency, so no
// distance tolerance is needed. Without this, a segment whose best partner
// went to a better match falls back to its second choice in the greedy
// assignment, and on repeated texture (tile courses, rows of windows) that is
// the neighbouring, wrong one. On a segment with two rival lines of equal
// score, both go.
std::vector<char> UnambiguousItems(const std::vector<AssignmentItem>& items);

// One-to-one, bidirectional matching as a global greedy assignment: items in
// decreasing score (ties: input order), an item is taken when none of its
// first two keys (the stereo pair) is taken yet; its further keys (support
// in other views) are taken along where still free. Deterministic,
// O(n log n). Unlike the mutual-best rule of ATOMI's bidirectional
// relaxation it lets a segment take its second choice; UnambiguousItems
// first removes the items that could. Returns, per item, the keys it got
// (empty when rejected).
std::vector<std::vector<std::pair<int, int>>> AssignOneToOne(
    const std::vector<AssignmentItem>& items);

}  // namespace roofsweep
