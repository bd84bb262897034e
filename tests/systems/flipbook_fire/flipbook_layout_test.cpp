// Groups of flipbook billboards (Rose 2007, sections 4.4-4.5): the thesis' overlapped pairs,
// triplets and grids expand to the positions, start frames and increments the thesis gives,
// and each billboard's colour is scaled by how many billboards overlap it.
#include <gtest/gtest.h>

#include <cmath>

#include "systems/flipbook_fire/flipbook_layout.h"

namespace pyro {
namespace {

TEST(FlipbookLayout, ThesisPairs) {
  FlipbookFire fire;
  fire.width = 0.3f;
  fire.groups.emplace_back();  // defaults: the thesis' three pairs
  const auto b = expand_flipbook_groups(fire);
  ASSERT_EQ(b.size(), 6u);
  for (int r = 0; r < 3; ++r) {
    const FlipbookBillboard& left = b[static_cast<size_t>(2 * r)];
    const FlipbookBillboard& right = b[static_cast<size_t>(2 * r + 1)];
    // Overlap 1/3 of the width: centres 2/3 w apart, symmetric about the axis.
    EXPECT_NEAR(left.lateral, -0.1f, 1e-6f);
    EXPECT_NEAR(right.lateral, 0.1f, 1e-6f);
    EXPECT_NEAR(right.lateral - left.lateral - fire.width, -fire.width / 3.0f, 1e-6f);
    // Pairs 0.19 apart, row 0 furthest; the pair's second texture 0.1 nearer.
    EXPECT_NEAR(left.depth, (r - 1) * 0.19f, 1e-6f);
    EXPECT_NEAR(right.depth - left.depth, 0.1f, 1e-6f);
    // Figure 12: starts 2 and 10, +1 per pair; m_k = 1, n_k = -2.
    EXPECT_EQ(left.start_frame, 2 + r);
    EXPECT_EQ(right.start_frame, 10 + r);
    EXPECT_EQ(left.increment, 1);
    EXPECT_EQ(right.increment, -2);
  }
}

TEST(FlipbookLayout, OverlapCountsAndIntensity) {
  FlipbookFire fire;
  fire.width = 0.4f;
  fire.intensity = 0.9f;
  fire.overlap_exponent = 1.0f;
  FlipbookGroup g;
  g.rows = 11;  // the thesis' 11 rows of 7, 0.4 apart laterally: each column covers its own line
  g.columns = 7;
  g.overlap = 0.0f;
  g.row_spacing = 0.2f;
  g.column_depths = {0.0f, 0.2f};
  fire.groups.push_back(g);
  auto b = expand_flipbook_groups(fire);
  ASSERT_EQ(b.size(), 77u);
  // Columns exactly one width apart touch at their edges: neighbours' edges reach this centre
  // line only when the overlap is at least 1/2. Here each line crosses its own column: 11.
  for (const FlipbookBillboard& x : b) {
    EXPECT_EQ(x.overlap_count, 11);
    EXPECT_NEAR(x.intensity, 0.9f / 11.0f, 1e-6f);
  }
  // With overlap 1/2 a centre line also meets both neighbouring columns' edges.
  fire.groups[0].overlap = 0.5f;
  fire.overlap_exponent = 0.5f;
  b = expand_flipbook_groups(fire);
  for (const FlipbookBillboard& x : b) {
    const int expected = 11 * (x.column == 0 || x.column == 6 ? 2 : 3);
    EXPECT_EQ(x.overlap_count, expected) << "column " << x.column;
    EXPECT_NEAR(x.intensity, 0.9f / std::sqrt(static_cast<float>(expected)), 1e-6f);
  }
}

TEST(FlipbookLayout, CycledColumnPatternsForTriplets) {
  FlipbookFire fire;
  FlipbookGroup g;
  g.rows = 2;
  g.columns = 3;
  g.column_depths = {0.0f, -0.1f};
  g.start_frames = {2, 10};
  g.increments = {-2, 1};
  fire.groups.push_back(g);
  const auto b = expand_flipbook_groups(fire);
  ASSERT_EQ(b.size(), 6u);
  // Columns 0, 1, 2 take pattern entries 0, 1, 0.
  EXPECT_EQ(b[0].increment, -2);
  EXPECT_EQ(b[1].increment, 1);
  EXPECT_EQ(b[2].increment, -2);
  EXPECT_EQ(b[2].start_frame, 2);
  EXPECT_EQ(b[5].start_frame, 3);
  EXPECT_NEAR(b[1].depth - b[0].depth, -0.1f, 1e-6f);
  EXPECT_NEAR(b[2].depth, b[0].depth, 1e-6f);
}

}  // namespace
}  // namespace pyro
