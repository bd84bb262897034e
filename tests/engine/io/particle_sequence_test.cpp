// Particle sequence manifests (engine/io/particle_sequence.h): written and read back, and every
// kind of damage refused naming the manifest, the JSON pointer and what was expected.
#include <gtest/gtest.h>

#include <fstream>

#include "engine/core/user_error.h"
#include "engine/io/particle_sequence.h"
#include "tests/support/particle_sequence_fixture.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::vector<std::vector<GaussianParticle>> three_frames() {
  return {{test::test_particle(0, 0, 0, 1, 0.5f)},
          {test::test_particle(1, 0, 0, 1, 0.5f), test::test_particle(2, 0, 0, 1, 0.5f)},
          {}};
}

void expect_refused(const fs::path& folder, const std::string& place, const std::string& fragment) {
  try {
    read_particle_sequence(folder.string());
    ADD_FAILURE() << "no error; expected one at " << place;
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), (folder / kParticleSequenceManifest).string()) << e.what();
    EXPECT_EQ(e.place(), place) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

void rewrite(const fs::path& folder, const std::string& from, const std::string& to) {
  std::ifstream in(folder / kParticleSequenceManifest);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::ofstream(folder / kParticleSequenceManifest, std::ios::trunc) << text;
}

TEST(ParticleSequence, RoundTripsTheManifest) {
  const fs::path dir = test::scratch_dir("roundtrip") / "s.pyroseq";
  const ParticleSequence written = test::write_test_sequence(dir, three_frames(), 12.5, 7);
  EXPECT_TRUE(is_particle_sequence(dir.string()));
  const ParticleSequence s = read_particle_sequence(dir.string());
  EXPECT_EQ(s.fps, 12.5);
  ASSERT_EQ(s.frames.size(), 3u);
  EXPECT_EQ(s.frames[0].number, 7);
  EXPECT_EQ(s.frames[2].number, 9);
  EXPECT_EQ(s.frames[1].file, "frame_000008.pyrop");
  EXPECT_EQ(s.frames[1].particles, 2u);
  EXPECT_TRUE(s.has_bounds);
  EXPECT_EQ(s.bounds_min[0], 0.0);
  EXPECT_EQ(s.bounds_max[0], 2.0);
  // Consecutive pairs hold 1 + 2 and 2 + 0, and a loop's last-to-first pair 0 + 1.
  EXPECT_EQ(s.max_pair_particles(), 3u);
  EXPECT_EQ(written.max_pair_particles(), 3u);
}

TEST(ParticleSequence, RefusesDamagedManifestsByPlace) {
  const fs::path dir = test::scratch_dir("damaged") / "s.pyroseq";
  test::write_test_sequence(dir, three_frames(), 24.0);
  rewrite(dir, "\"number\": 2", "\"number\": 3");
  expect_refused(dir, "/frames/1/number", "frame number 2");

  test::write_test_sequence(dir, three_frames(), 24.0);
  fs::remove(dir / "frame_000003.pyrop");
  expect_refused(dir, "/frames/2/file", "an existing particle file");

  test::write_test_sequence(dir, three_frames(), 24.0);
  rewrite(dir, "\"fps\": 24.0", "\"fps\": 0");
  expect_refused(dir, "/fps", "a number in (0, 1e+06]");

  test::write_test_sequence(dir, three_frames(), 24.0);
  rewrite(dir, "\"file\": \"frame_000001.pyrop\"", "\"file\": \"../x.pyrop\"");
  expect_refused(dir, "/frames/0/file", "a plain file name");

  test::write_test_sequence(dir, three_frames(), 24.0);
  rewrite(dir, "\"version\": 1", "\"version\": 2");
  expect_refused(dir, "/version", "an integer in [1, 1]");
}

}  // namespace
}  // namespace pyro
