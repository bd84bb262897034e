#include "engine/core/edit_distance.h"

#include <algorithm>
#include <utility>

namespace pyro {

// Wagner & Fischer's recurrence (J. ACM 21(1), 1974) with the transposition case, kept in three
// rows over the shorter string: O(min(m, n)) memory, O(m n) time.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  if (a.size() < b.size()) std::swap(a, b);  // b is the shorter: rows of b.size() + 1
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> before(m + 1), previous(m + 1), row(m + 1);
  for (std::size_t j = 0; j <= m; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[m];
}

std::string_view closest_candidate(std::string_view wrong, const std::vector<std::string_view>& candidates,
                                   std::size_t max_distance) {
  constexpr std::size_t kSuggestLimit = 64;
  if (wrong.size() > kSuggestLimit) return {};
  std::string_view best;
  std::size_t best_distance = max_distance + 1;
  for (std::string_view c : candidates) {
    const std::size_t gap = wrong.size() > c.size() ? wrong.size() - c.size() : c.size() - wrong.size();
    if (gap >= best_distance) continue;  // the distance is at least the gap
    const std::size_t dist = edit_distance(wrong, c);
    if (dist < best_distance) best_distance = dist, best = c;
  }
  return best;
}

}  // namespace pyro
