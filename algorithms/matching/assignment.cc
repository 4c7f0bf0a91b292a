#include "algorithms/matching/assignment.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

namespace roofsweep {

std::vector<char> UnambiguousItems(const std::vector<AssignmentItem>& items) {
  using Key = std::pair<int, int>;
  std::map<Key, std::vector<int>> by_segment;  // items matching a segment
  for (size_t n = 0; n < items.size(); ++n)
    if (items[n].keys.size() >= 2)
      for (int k = 0; k < 2; ++k) by_segment[items[n].keys[k]].push_back(static_cast<int>(n));
  auto uses = [&](int n, const Key& key) {
    const auto& k = items[n].keys;
    return std::find(k.begin(), k.end(), key) != k.end();
  };
  std::vector<char> out(items.size(), 1);
  for (size_t n = 0; n < items.size(); ++n) {
    const auto& kn = items[n].keys;
    if (kn.size() < 2) continue;
    for (int side = 0; side < 2 && out[n]; ++side) {
      const Key& shared = kn[side];
      const Key& partner = kn[1 - side];
      for (int m : by_segment[shared]) {
        if (m == static_cast<int>(n) || items[m].score < items[n].score) continue;
        const auto& km = items[m].keys;
        const Key& rival = km[0] == shared ? km[1] : km[0];
        if (uses(static_cast<int>(n), rival) || uses(m, partner)) continue;  // the same line
        out[n] = 0;
        break;
      }
    }
  }
  return out;
}

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
