// Error near depth edges (engine/math/depth_edge_error.h) on synthetic images whose edges,
// distances and errors are known in closed form.
#include "engine/math/depth_edge_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "engine/core/rng.h"

namespace pyro {
namespace {

constexpr int W = 40, H = 24;
constexpr int step_column = 19;  // the last column of the near surface

// Near on the left (z = 2, columns 0..19), far on the right (z = 5).
std::vector<float> step_depth() {
  std::vector<float> z(W * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) z[y * W + x] = x <= step_column ? 2.0f : 5.0f;
  return z;
}

TEST(DepthEdges, AStepMarksTheLastNearAndTheFirstFarColumn) {
  const DepthEdges e = find_depth_edges(W, H, step_depth(), 0.05f);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      EXPECT_EQ(e.near_side[y * W + x], x == step_column) << x << " " << y;
      EXPECT_EQ(e.far_side[y * W + x], x == step_column + 1) << x << " " << y;
    }
}

TEST(DepthEdges, APlaneHasNoneHoweverSteep) {
  // 1/z affine in the pixel position: z from 0.5 to 40 across the image.
  std::vector<float> z(W * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) z[y * W + x] = 1.0f / (2.0f - 0.048f * x - 0.002f * y);
  const DepthEdges e = find_depth_edges(W, H, z, 0.05f);
  for (size_t i = 0; i < z.size(); ++i) EXPECT_FALSE(e.near_side[i] || e.far_side[i]) << i;
}

TEST(DepthEdges, BadInputIsRefused) {
  std::vector<float> z = step_depth();
  EXPECT_THROW(find_depth_edges(W, H + 1, z, 0.05f), std::invalid_argument);
  z[7] = 0.0f;
  EXPECT_THROW(find_depth_edges(W, H, z, 0.05f), std::invalid_argument);
  EXPECT_THROW(find_depth_edges(0, H, {}, 0.05f), std::invalid_argument);
}

TEST(ChessboardDistance, MatchesBruteForce) {
  Rng rng(7, 3);
  std::vector<uint8_t> mask(W * H, 0);
  for (uint8_t& m : mask) m = rng.uniform() < 0.02f;
  const std::vector<int> d = chessboard_distance(W, H, mask);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      int best = 1 << 30;
      for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u)
          if (mask[v * W + u]) best = std::min(best, std::max(std::abs(u - x), std::abs(v - y)));
      if (best < (1 << 30))
        EXPECT_EQ(d[y * W + x], best) << x << " " << y;
      else
        EXPECT_GT(d[y * W + x], W + H);
    }
}

struct Images {
  std::vector<float> depth = step_depth();
  std::vector<float> scene = std::vector<float>(4 * W * H, 0.25f);
  std::vector<float> reference = scene, measured = scene;
  std::vector<float> particle_far = std::vector<float>(W * H, 10.0f);
  DepthEdgeInputs inputs() const { return {W, H, depth, scene, reference, measured, particle_far}; }
};

void add(std::vector<float>& rgba, int x, int y, float v) {
  for (int c = 0; c < 3; ++c) rgba[4 * (y * W + x) + c] += v;
}

TEST(DepthEdgeError, EdgeRmseCountsThePixelsWithinFourOfTheEdge) {
  Images im;
  add(im.measured, step_column - 3, 5, 0.3f);  // 3 from the near edge pixel: counted
  add(im.measured, step_column + 5, 6, 0.2f);  // 4 from the far edge pixel: counted
  add(im.measured, step_column - 5, 7, 0.5f);  // 5 from both: not
  const DepthEdgeError e = depth_edge_error(im.inputs());
  // Columns step_column - 4 .. step_column + 1 + 4, every row.
  const size_t pixels = 10 * H;
  EXPECT_EQ(e.edge_pixels, pixels);
  EXPECT_NEAR(e.edge_rmse, std::sqrt((0.3 * 0.3 + 0.2 * 0.2) * 3 / (3.0 * pixels)), 1e-7);
}

TEST(DepthEdgeError, HaloIsLightOnTheNearSideBeyondTwoPixels) {
  Images im;
  // The reference lights the far side next to the edge (particles the near surface hides) in
  // rows 0..11; the near side shows the scene alone.
  for (int y = 0; y < 12; ++y) add(im.reference, step_column + 1, y, 0.4f);
  im.measured = im.reference;
  add(im.measured, step_column - 1, 3, 0.5f);    // 2 from the far side: within the bound
  add(im.measured, step_column - 2, 4, 0.125f);  // 3 from it: a halo
  add(im.measured, step_column - 6, 2, 0.0625f);
  add(im.measured, step_column + 3, 5, 0.7f);  // on the far side: none
  DepthEdgeError e = depth_edge_error(im.inputs());
  EXPECT_DOUBLE_EQ(e.halo, 0.125);
  // Near-side columns 0 .. step_column - 2 within 16 of a lit far pixel: columns
  // step_column - 15 .. step_column - 2 (14), rows 0 .. 11 + 16 (all 24).
  EXPECT_EQ(e.halo_pixels, size_t(14 * H));
  EXPECT_NEAR(e.halo_rms, std::sqrt((0.125 * 0.125 + 0.0625 * 0.0625) * 3 / (3.0 * 14 * H)), 1e-7);
  // Particles wholly in front of the near surface: nothing to hide, no halo.
  for (float& f : im.particle_far) f = 1.5f;
  e = depth_edge_error(im.inputs());
  EXPECT_EQ(e.halo_pixels, 0u);
  EXPECT_EQ(e.halo, 0.0);
}

TEST(DepthEdgeError, AnOutlineOnTheNearSideIsNoHalo) {
  // Particles in front of the near surface light its columns 0..5 in the reference; others behind
  // it light the far side next to the edge. Light the upsampling spreads from the near side's
  // own particles (nearer them than the far side's light) is their outline blurred, not a halo.
  Images im;
  for (int y = 0; y < 12; ++y) {
    add(im.reference, step_column + 1, y, 0.4f);
    for (int x = 0; x <= 5; ++x) add(im.reference, x, y, 0.3f);
  }
  im.measured = im.reference;
  add(im.measured, 7, 3, 0.25f);                // 2 from the near light, 13 from the far: outline
  add(im.measured, step_column - 3, 4, 0.125f);  // 4 from the far light, 13 from the near: halo
  const DepthEdgeError e = depth_edge_error(im.inputs());
  EXPECT_DOUBLE_EQ(e.halo, 0.125);
  // Near-side pixels beyond 2 from the far side (x <= step_column - 2 = 17) and nearer the far
  // light (column 20, rows 0..11) than the near one (columns 0..5, rows 0..11). Below row 11
  // both distances share d = y - 11: max(20 - x, d) < max(x - 5, d) holds for x >= 13 and
  // d < x - 5, so column x counts rows 0 .. x + 5: 19 + 20 + 21 + 22 + 23 for x = 13..17.
  EXPECT_EQ(e.halo_pixels, size_t(19 + 20 + 21 + 22 + 23));
}

TEST(DepthEdgeError, MismatchedImagesAreRefused) {
  Images im;
  im.measured.pop_back();
  EXPECT_THROW(depth_edge_error(im.inputs()), std::invalid_argument);
}

}  // namespace
}  // namespace pyro
