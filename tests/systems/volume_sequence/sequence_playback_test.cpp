// A particle sequence in a scene (systems/volume_sequence): a ranged run reads only the source
// frames its drawn frames need, the window of loaded frames stays small, and the scene's
// playback keys are checked against the sequence.
#include <gtest/gtest.h>

#include "components/particle_set.h"
#include "components/volume_sequence.h"
#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/particle_sequence_fixture.h"
#include "tests/support/small_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// Ten frames, frame i a particle at x = i, played at 15 source fps in a 30 fps scene: scene
// frame f shows source position f / 2.
SceneDescription ten_frame_scene(const fs::path& dir, const std::string& keys = "") {
  std::vector<std::vector<GaussianParticle>> frames;
  for (int i = 0; i < 10; ++i) frames.push_back({test::test_particle(float(i), 0, 0, 0.5f, 0.5f)});
  test::write_test_sequence(dir / "s.pyroseq", frames, 15.0);
  const std::string text = R"({"output": {"fps": 30}, "volumes": [{"file": "s.pyroseq", "anchor": "origin")" +
                           keys + "}]}";
  return parse_scene(text, (dir / "scene.json").string());
}

VolumeSequence& sequence_of(SceneRuntime& runtime) {
  VolumeSequence* found = nullptr;
  runtime.world().each<VolumeSequence>([&](ecs::Entity, VolumeSequence& s) { found = &s; });
  EXPECT_NE(found, nullptr);
  return *found;
}

TEST(SequencePlayback, ARangeReadsOnlyTheSourceFramesItDraws) {
  const fs::path dir = test::scratch_dir("range");
  SceneRuntime runtime(ten_frame_scene(dir), test::small_runtime());
  EXPECT_TRUE(sequence_of(runtime).reads.empty());  // nothing read before a frame is drawn
  runtime.draw_frames({8, 9}, {});
  // Frame 8 is source frame 4 alone; frame 9 is 4.5: frames 4 and 5 cross-faded.
  EXPECT_EQ(sequence_of(runtime).reads, (std::vector<std::size_t>{4, 5}));
  const VolumeSequence& s = sequence_of(runtime);
  EXPECT_EQ(s.frame_a, 4u);
  EXPECT_EQ(s.frame_b, 5u);
  EXPECT_DOUBLE_EQ(s.weight, 0.5);
}

TEST(SequencePlayback, AFullRunReadsEachFrameOnceWithinTheWindow) {
  const fs::path dir = test::scratch_dir("full");
  SceneRuntime runtime(ten_frame_scene(dir), test::small_runtime());
  for (int f = 0; f < 24; ++f) {
    runtime.draw_frame(f);
    EXPECT_LE(sequence_of(runtime).loaded.size(), sequence_of(runtime).window);
  }
  EXPECT_EQ(sequence_of(runtime).reads, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  // Past the last frame (position 11.5) the sequence holds frame 9: one particle at x = 9.
  const ParticlePool* pool = nullptr;
  runtime.world().each<ParticleSet, VolumeSequence>(
      [&](ecs::Entity, ParticleSet& p, VolumeSequence&) { pool = &p.pool; });
  ASSERT_EQ(pool->size(), 1u);
  EXPECT_EQ(pool->px[0], 9.0f);
  EXPECT_EQ(pool->density[0], 0.5f);
}

TEST(SequencePlayback, StartFrameSpeedAndLoopPlaceTheSourcePosition) {
  const fs::path dir = test::scratch_dir("keys");
  // Start at source frame 9 (index 8), twice as fast, looping: frame 1 is position 8 + 1 = 9,
  // frame 2 is 10 = 0 after the wrap.
  SceneRuntime runtime(ten_frame_scene(dir, R"(, "start_frame": 9, "speed": 2, "loop": true)"),
                       test::small_runtime());
  runtime.draw_frame(1);
  EXPECT_EQ(sequence_of(runtime).frame_a, 9u);
  runtime.draw_frame(2);
  EXPECT_EQ(sequence_of(runtime).frame_a, 0u);
  EXPECT_EQ(sequence_of(runtime).weight, 0.0);
}

TEST(SequencePlayback, PlaybackKeysAreCheckedAgainstTheSequence) {
  const fs::path dir = test::scratch_dir("bad_keys");
  const SceneDescription scene = ten_frame_scene(dir, R"(, "start_frame": 11)");
  try {
    SceneRuntime runtime(scene, test::small_runtime());
    ADD_FAILURE() << "a start frame past the sequence was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.place(), "/volumes/0/start_frame") << e.what();
    EXPECT_NE(std::string(e.what()).find("in [1, 10], found 11"), std::string::npos) << e.what();
  }
  for (const std::string& keys : {std::string(R"(, "speed": 0)"), std::string(R"(, "loop": 1)"),
                                   std::string(R"(, "start_frame": -1)"), std::string(R"(, "error": 0.1)")}) {
    EXPECT_THROW(ten_frame_scene(dir, keys), UserError) << keys;
  }
  // The playback keys mean nothing for a single particle file.
  test::write_test_sequence(dir / "one.pyroseq", {{test::test_particle(0, 0, 0, 1, 0.5f)}}, 24.0);
  EXPECT_THROW(parse_scene(R"({"volumes": [{"file": "one.pyroseq/frame_000001.pyrop", "loop": true}]})",
                           (dir / "scene.json").string()),
               UserError);
}

}  // namespace
}  // namespace pyro
