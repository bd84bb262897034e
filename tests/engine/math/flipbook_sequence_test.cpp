// Frame indices of flipbook billboards (Rose 2007, section 4.4): start + t * increment, looping
// over n frames, for increments of either sign; checked against stepping a counter by hand.
#include <gtest/gtest.h>

#include "engine/math/flipbook_sequence.h"

namespace pyro {
namespace {

TEST(FlipbookSequence, MatchesAHandSteppedCounterForEverySignAndStart) {
  for (int n : {1, 2, 7, 32, 34})
    for (int start : {-70, -3, 0, 2, 10, 33, 99})
      for (int increment : {-5, -2, -1, 0, 1, 2, 3, 37}) {
        int frame = ((start % n) + n) % n;  // the counter, wrapped by hand at each step
        for (int t = 0; t < 3 * n + 5; ++t) {
          ASSERT_EQ(flipbook_frame(start, increment, t, n), frame)
              << "n " << n << " start " << start << " increment " << increment << " t " << t;
          frame += increment;
          while (frame < 0) frame += n;
          while (frame >= n) frame -= n;
        }
      }
}

TEST(FlipbookSequence, ThesisExampleAndLargeSteps) {
  // k = 1 of the thesis' figure 12 with n = 34: 2, 3, 4, ... on the left (m = 1) and
  // 10, 8, 6, ..., 0, 32, ... on the right (n_k = -2).
  EXPECT_EQ(flipbook_frame(2, 1, 0, 34), 2);
  EXPECT_EQ(flipbook_frame(2, 1, 32, 34), 0);
  EXPECT_EQ(flipbook_frame(10, -2, 5, 34), 0);
  EXPECT_EQ(flipbook_frame(10, -2, 6, 34), 32);
  // No overflow for steps far beyond a loop: (s + t m) mod n computed exactly.
  const int64_t t = 2'000'000'000;
  EXPECT_EQ(flipbook_frame(3, -7, t, 34), static_cast<int>(((3 - 7 * (t % 34)) % 34 + 34) % 34));
  EXPECT_THROW(flipbook_frame(0, 1, 0, 0), std::invalid_argument);
}

TEST(FlipbookSequence, StepOfSceneTime) {
  // Frame f of a 30 fps scene at 30 flipbook steps per second is step f, though f * (1/30)
  // rounds below f / 30 for some f.
  for (int f = 0; f < 1000; ++f) EXPECT_EQ(flipbook_step(f * (1.0f / 30.0f), 30.0), f) << f;
  EXPECT_EQ(flipbook_step(1.0, 15.0), 15);
  EXPECT_EQ(flipbook_step(0.99, 15.0), 14);
}

}  // namespace
}  // namespace pyro
