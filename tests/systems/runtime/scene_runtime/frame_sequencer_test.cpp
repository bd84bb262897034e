// The runtime's last layer: which steps make which output frames. Alone, against a recording
// stepper (substeps, the motion-blur prefix, ascending frames), then on real scenes: frames A..B
// of a run equal the same frames of a full run byte for byte, with and without motion blur and
// with substeps.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/frame_sequencer.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/small_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

// Records "s<frame>" for a simulate-only step and "D<frame>" for a drawing step.
class RecordingStepper : public FrameStepper {
 public:
  uint64_t frame() const override { return frame_; }
  void step() override { log.push_back("D" + std::to_string(frame_++)); }
  void simulate_step() override { log.push_back("s" + std::to_string(frame_++)); }
  std::vector<std::string> log;

 private:
  uint64_t frame_ = 0;
};

using Log = std::vector<std::string>;

TEST(FrameSequencer, FramesBeforeTheFirstAreSimulatedNotDrawn) {
  RecordingStepper r;
  FrameSequencer s(1, false);
  std::vector<int> drawn;
  s.draw(r, FrameRange{2, 3}, [&](int f) { drawn.push_back(f); });
  EXPECT_EQ(r.log, (Log{"s0", "s1", "D2", "D3"}));
  EXPECT_EQ(drawn, (std::vector<int>{2, 3}));
  EXPECT_EQ(s.next_frame(), 4);
}

TEST(FrameSequencer, SubstepsSimulateBetweenDrawnFrames) {
  RecordingStepper r;
  FrameSequencer s(3, false);
  s.draw(r, 1);  // runtime frame 3
  s.draw(r, 2);  // runtime frame 6
  EXPECT_EQ(r.log, (Log{"s0", "s1", "s2", "D3", "s4", "s5", "D6"}));
  EXPECT_EQ(s.runtime_frame(5), 15u);
}

TEST(FrameSequencer, MotionBlurDrawsEveryEarlierOutputFrame) {
  RecordingStepper r;
  FrameSequencer s(2, true);
  s.draw(r, FrameRange{2, 2}, nullptr);
  // Output frames 0 and 1 are drawn (runtime frames 0 and 2), with the substeps between.
  EXPECT_EQ(r.log, (Log{"D0", "s1", "D2", "s3", "D4"}));
  r.log.clear();
  s.draw(r, 4);  // frame 3 drawn first, so that 4 blends over it
  EXPECT_EQ(r.log, (Log{"s5", "D6", "s7", "D8"}));
}

TEST(FrameSequencer, RefusesFramesThatDoNotAscend) {
  RecordingStepper r;
  FrameSequencer s(1, false);
  s.draw(r, 3);
  EXPECT_THROW(s.draw(r, 3), std::logic_error);
  EXPECT_THROW(s.draw(r, 1), std::logic_error);
  r.step();  // the caller ran past frame 4 itself
  EXPECT_THROW(s.draw(r, 4), std::logic_error);
  EXPECT_NO_THROW(s.draw(r, 5));
  EXPECT_THROW(FrameSequencer(0, false), std::invalid_argument);
}

// The shown image of output frames first..last, from a runtime that draws only those.
std::vector<std::vector<uint8_t>> frames_of_frame_sequencer(const SceneDescription& scene, const RuntimeOptions& o,
                                            FrameRange range) {
  SceneRuntime runtime(scene, o);
  std::vector<std::vector<uint8_t>> out;
  runtime.draw_frames(range, [&](int) { out.push_back(runtime.read_output().rgba); });
  return out;
}

void expect_range_matches_full_run(const SceneDescription& scene, const RuntimeOptions& o) {
  const auto full = frames_of_frame_sequencer(scene, o, {0, 5});
  const auto part = frames_of_frame_sequencer(scene, o, {4, 5});
  ASSERT_EQ(full.size(), 6u);
  ASSERT_EQ(part.size(), 2u);
  EXPECT_TRUE(full[4] == part[0]);
  EXPECT_TRUE(full[5] == part[1]);
  EXPECT_FALSE(full[3] == full[4]);  // the frames differ: the comparison can fail
}

TEST(FrameSequencerRun, ARangeEqualsTheSameFramesOfAFullRun) {
  expect_range_matches_full_run(load_scene(test::scene_path("explosion.json")), test::small_runtime());
}

TEST(FrameSequencerRun, ARangeEqualsAFullRunWithMotionBlur) {
  SceneDescription scene = load_scene(test::scene_path("explosion.json"));
  scene.render.motion_blur = 0.6f;
  expect_range_matches_full_run(scene, test::small_runtime());
  // Without the drawn prefix the blend would start at frame 4 and differ.
  SceneRuntime unblurred_prefix(scene, test::small_runtime());
  for (int f = 0; f < 4; ++f) unblurred_prefix.simulate_step();
  unblurred_prefix.step();
  EXPECT_FALSE(unblurred_prefix.read_output().rgba == frames_of_frame_sequencer(scene, test::small_runtime(), {4, 4})[0]);
}

TEST(FrameSequencerRun, ARangeEqualsAFullRunWithSubsteps) {
  RuntimeOptions o = test::small_runtime();
  o.quality = QualitySettings{1.0f, 64, 2};
  expect_range_matches_full_run(load_scene(test::scene_path("explosion.json")), o);
}

}  // namespace
}  // namespace pyro
