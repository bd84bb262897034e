// Which source frames a particle sequence draws at a scene time (sequence_clock.h), and the
// cross-fade's densities (sequence_frames.h) against their closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "systems/volume_sequence/sequence_clock.h"
#include "systems/volume_sequence/sequence_frames.h"
#include "tests/support/particle_sequence_fixture.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

// The frames drawn at position s of `count` frames: a, b and b's weight (all exact: quarters).
void expect_sample(double s, std::size_t count, bool loop, std::size_t a, std::size_t b, double weight) {
  const SequenceSample got = sample_sequence(s, count, loop);
  EXPECT_EQ(got.a, a) << "at " << s;
  EXPECT_EQ(got.b, b) << "at " << s;
  EXPECT_EQ(got.weight, weight) << "at " << s;
}

TEST(SequenceClock, PositionsBracketAndWeighTheSourceFrames) {
  // 24 fps played at 30 fps: frame 5 is 4 source frames in, from start index 2.
  EXPECT_EQ(sequence_position(5, 30.0, 24.0, 2), 6.0);
  expect_sample(2.25, 5, false, 2, 3, 0.25);
  expect_sample(3.0, 5, false, 3, 3, 0.0);
}

TEST(SequenceClock, AFrameLandingOnASourceFrameDrawsItAlone) {
  // 24 source fps at 30 (0.8) lands on a source frame every fifth frame; 23.976 source fps at
  // speed 1.25 is 29.97, played in a scene of 29.97 fps stored as a float (3e-8 off): every
  // frame lands on one.
  for (uint64_t f : {5ull, 35ull, 240ull, 100000ull, 10000000ull}) {
    EXPECT_EQ(sequence_position(f, double(30.0f), 24.0, 0), double(f / 5 * 4)) << f;
    EXPECT_EQ(sample_sequence(sequence_position(f, 30.0, 24.0, 0), 100000000, false).weight, 0.0) << f;
  }
  EXPECT_EQ(sequence_position(3, double(29.97f), 23.976 * 1.25, 0), 3.0);
  EXPECT_EQ(sequence_position(3000, double(29.97f), 23.976 * 1.25, 0), 3000.0);
  EXPECT_NEAR(sequence_position(3, 30.0, 10.0, 0), 1.0, 0.0);
  EXPECT_DOUBLE_EQ(sequence_position(4, 30.0, 10.0, 0), 4.0 / 3.0);
}

TEST(SequenceClock, LoopsWrapIntoTheFirstFrameAndOthersHoldTheLast) {
  expect_sample(7.5, 4, false, 3, 3, 0.0);
  expect_sample(3.5, 4, true, 3, 0, 0.5);  // between the last and the first
  expect_sample(9.25, 4, true, 1, 2, 0.25);
}

TEST(SequenceCrossFade, FadedDensityScalesTheOpticalDepth) {
  for (double rho : {0.0, 0.1, 0.5, 0.9}) {
    for (double w : {0.0, 0.25, 0.5, 1.0}) {
      const double tau = -std::log(1.0 - rho);
      const double faded = faded_density(float(rho), w);
      EXPECT_NEAR(-std::log(1.0 - faded), w * tau, 1e-6) << rho << " " << w;
    }
  }
  EXPECT_EQ(faded_density(0.3f, 1.0), 0.3f);
}

// Frame a's and frame b's particles over one point: the transmittance through both, at weight w,
// is exp(-((1 - w) tau_a + w tau_b)), the linear interpolation of the density field.
TEST(SequenceCrossFade, TwoFramesInterpolateTheDensityFieldLinearly) {
  const auto dir = test::scratch_dir("crossfade") / "s.pyroseq";
  const float rho_a = 0.5f, rho_b = 0.9f;
  test::write_test_sequence(dir, {{test::test_particle(1, 2, 3, 1, rho_a)}, {test::test_particle(1, 2, 3, 1, rho_b)}},
                            24.0);
  VolumeSequence s;
  s.frames = {{(dir / "frame_000001.pyrop").string(), 1}, {(dir / "frame_000002.pyrop").string(), 1}};
  s.anchor = {1, 2, 3};
  s.at = {0, 0, -5};
  ParticlePool pool(2);
  const double w = 0.25;
  fill_sequence_particles(s, sample_sequence(w, 2, false), pool);
  ASSERT_EQ(pool.size(), 2u);
  const double through = (1.0 - pool.density[0]) * (1.0 - pool.density[1]);
  const double expected = std::exp(-((1 - w) * -std::log(1.0 - rho_a) + w * -std::log(1.0 - rho_b)));
  EXPECT_NEAR(through, expected, 1e-6);
  // Not the linear interpolation of the opacities (which would give 1 - 0.6).
  EXPECT_GT(std::abs(through - 0.4), 0.05);
  EXPECT_EQ(pool.pz[0], -5.0f);
  EXPECT_EQ(pool.id[1], 1u);
  EXPECT_EQ(s.reads, (std::vector<std::size_t>{0, 1}));
}

TEST(SequenceCrossFade, TheWindowKeepsAFewFramesAndReadsEachOnceGoingForward) {
  const auto dir = test::scratch_dir("window") / "s.pyroseq";
  std::vector<std::vector<GaussianParticle>> frames;
  for (int i = 0; i < 10; ++i) frames.push_back({test::test_particle(float(i), 0, 0, 1, 0.5f)});
  test::write_test_sequence(dir, frames, 24.0);
  VolumeSequence s;
  for (int i = 0; i < 10; ++i) s.frames.push_back({(dir / particle_sequence_frame_name(i + 1)).string(), 1});
  ParticlePool pool(2);
  for (uint64_t f = 0; f < 40; ++f) {
    fill_sequence_particles(s, sample_sequence(sequence_position(f, 30.0, 7.0, 0), 10, false), pool);
    EXPECT_LE(s.loaded.size(), s.window);
  }
  EXPECT_EQ(s.reads, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

}  // namespace
}  // namespace pyro
