#include "algorithms/matching/assignment.h"

#include <algorithm>
#include <numeric>
#include <set>

namespace roofsweep {

std::vector<std::vector<std::pair<int, int>>> AssignOneToOne(
    const std::vector<AssignmentItem>& items) {
  std::vector<int> order(items.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return items[a].score > items[b].score; });
  std::set<std::pair<int, int>> taken;
  std::vector<std::vector<std::pair<int, int>>> out(items.size());
  for (int i : order) {
    const auto& k = items[i].keys;
    if (k.size() < 2 || taken.count(k[0]) || taken.count(k[1])) continue;
    for (size_t m = 0; m < k.size(); ++m) {
      if (m >= 2 && taken.count(k[m])) continue;
      // One observation per view and track.
      bool same_view = false;
      for (const auto& have : out[i]) same_view |= have.first == k[m].first;
      if (same_view) continue;
      taken.insert(k[m]);
      out[i].push_back(k[m]);
    }
  }
  return out;
}

}  // namespace roofsweep
