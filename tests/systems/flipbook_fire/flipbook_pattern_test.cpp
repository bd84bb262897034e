// The "march" and "circle" failure modes of flipbook frame patterns (Rose 2007, section 4.4) as
// numbers (systems/flipbook_fire/flipbook_pattern.h), against closed forms worked out from the
// thesis' pair layout.
#include <gtest/gtest.h>

#include <cmath>

#include "systems/flipbook_fire/flipbook_layout.h"
#include "systems/flipbook_fire/flipbook_pattern.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

PatternMotion pairs_with(std::vector<int> increments, int frames = 32) {
  FlipbookFire fire;
  fire.width = 0.3f;
  fire.groups.emplace_back().increments = std::move(increments);
  return measure_pattern_motion(expand_flipbook_groups(fire), frames);
}

// Tangential component of a unit transfer u at midpoint m about centroid c (counter-clockwise).
double tangential(glm::dvec2 u, glm::dvec2 m, glm::dvec2 c) {
  const glm::dvec2 r = m - c;
  return (u.x * -r.y + u.y * r.x) / std::sqrt(r.x * r.x + r.y * r.y);
}

TEST(FlipbookPattern, AllPlusOneMarchesAwayFromTheViewer) {
  // Column c, row r shows s_c + r + t: row r at t + 1 shows what row r + 1 (nearer) showed at t,
  // so every step each column moves its content one row away: 2 columns x 2 row pairs = 4
  // transfers per step among 6 billboards, all along -depth.
  const PatternMotion m = pairs_with({1, 1});
  EXPECT_NEAR(m.march, 4.0 / 6.0, 1e-12);
  EXPECT_NEAR(m.march_direction.y, -1.0f, 1e-6f);
  EXPECT_NEAR(m.transfers, 4.0 / 6.0, 1e-12);
  // Both columns move the same way: no net rotation.
  EXPECT_NEAR(m.circulation, 0.0, 0.05);
}

TEST(FlipbookPattern, PlusOneMinusOneCircles) {
  // Left column (x = -0.1, row depths -0.19, 0, 0.19) moves away, right column (x = 0.1, depths
  // -0.09, 0.1, 0.29) moves toward the viewer: no net translation, a rotation about the axis.
  const PatternMotion m = pairs_with({1, -1});
  EXPECT_NEAR(m.march, 0.0, 1e-12);
  const glm::dvec2 c(0.0, 0.05);  // centroid of the six billboards
  double sum = 0.0;
  for (double y : {-0.095, 0.095}) sum += tangential({0, -1}, {-0.1, y}, c);
  for (double y : {0.005, 0.195}) sum += tangential({0, 1}, {0.1, y}, c);
  EXPECT_NEAR(m.circulation, std::fabs(sum) / 6.0, 1e-5);
  EXPECT_GT(m.circulation, 0.45);
}

TEST(FlipbookPattern, ThesisIncrementsHalveTheCoherentMotion) {
  // m = 1, n = -2: the right column's content jumps two rows a step (row r - 2 to row r), which
  // is no neighbour transfer; only the left column still moves one row a step.
  const PatternMotion thesis = pairs_with({1, -2});
  const PatternMotion march = pairs_with({1, 1});
  const PatternMotion circle = pairs_with({1, -1});
  EXPECT_NEAR(thesis.march, 2.0 / 6.0, 1e-12);
  EXPECT_NEAR(thesis.circulation, circle.circulation / 2.0, 1e-5);
  EXPECT_LT(thesis.march, 0.51 * march.march);
  EXPECT_LT(thesis.circulation, 0.51 * circle.circulation);
}

// A frame moves from row a to row b in one step exactly when start_b - start_a is -increment
// (mod the frame count): rows started 7 frames apart (no +-1, +-2 with 32 frames) keep the
// thesis' increments without their coherent motion, as content/scenes/campfire.json does; the
// thesis' one frame apart marches.
TEST(FlipbookPattern, RowStartsApartFromEveryIncrementRemoveTheMarchAndTheCircle) {
  const SceneDescription campfire = load_scene(test::scene_path("campfire.json"));
  ASSERT_EQ(campfire.fires.size(), 1u);
  for (const FlipbookFire& fire : campfire.fires) {
    const PatternMotion m = measure_pattern_motion(expand_flipbook_groups(fire), 32);
    EXPECT_EQ(m.march, 0.0);
    EXPECT_EQ(m.circulation, 0.0);
    EXPECT_LT(m.transfers, 0.05);  // isolated hand-overs where columns of unlike increments meet
    FlipbookFire thesis = fire;
    for (FlipbookGroup& g : thesis.groups) g.row_start_step = 1;
    EXPECT_GT(measure_pattern_motion(expand_flipbook_groups(thesis), 32).march, 0.1);
  }
}

}  // namespace
}  // namespace pyro
