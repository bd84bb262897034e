#include "systems/flipbook_fire/flipbook_layout.h"

#include <cmath>

namespace pyro {

namespace {
template <typename T>
T cycled(const std::vector<T>& values, int index, T fallback) {
  if (values.empty()) return fallback;
  return values[static_cast<size_t>(index) % values.size()];
}
}  // namespace

int overlap_count(const std::vector<FlipbookBillboard>& billboards, size_t k, float width) {
  const float x = billboards[k].lateral;
  const float half = 0.5f * width;
  int count = 0;
  // A small tolerance: neighbours that just touch the centre line count.
  for (const FlipbookBillboard& b : billboards)
    if (std::fabs(b.lateral - x) <= half * (1.0f + 1e-5f)) ++count;
  return count;
}

std::vector<FlipbookBillboard> expand_flipbook_groups(const FlipbookFire& fire) {
  std::vector<FlipbookBillboard> out;
  for (size_t g = 0; g < fire.groups.size(); ++g) {
    const FlipbookGroup& group = fire.groups[g];
    const float column_spacing = fire.width * (1.0f - group.overlap);
    for (int r = 0; r < group.rows; ++r) {
      for (int c = 0; c < group.columns; ++c) {
        FlipbookBillboard b;
        b.lateral = group.offset.x + (c - 0.5f * (group.columns - 1)) * column_spacing;
        b.depth = group.offset.y + (r - 0.5f * (group.rows - 1)) * group.row_spacing +
                  cycled(group.column_depths, c, 0.0f);
        b.start_frame = cycled(group.start_frames, c, 0) + r * group.row_start_step;
        b.increment = cycled(group.increments, c, 1);
        b.group = static_cast<int>(g);
        b.row = r;
        b.column = c;
        out.push_back(b);
      }
    }
  }
  for (size_t k = 0; k < out.size(); ++k) {
    out[k].overlap_count = overlap_count(out, k, fire.width);
    out[k].intensity =
        fire.intensity / std::pow(static_cast<float>(out[k].overlap_count), fire.overlap_exponent);
  }
  return out;
}

}  // namespace pyro
