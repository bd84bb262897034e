// Animated VDB sequences imported frame by frame (systems/runtime/cloud_import/vdb_sequence_import.h):
// the puff generator's frames differ as the puff moves, every frame is an ordinary particle
// file of the one medium, an empty frame imports as 0 particles, and a damaged member is refused
// by name before any frame is imported.
#include <gtest/gtest.h>

#include <fstream>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "engine/volume/puff_sequence.h"
#include "systems/runtime/cloud_import/vdb_sequence_import.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

PuffSequenceOptions small_puff(int frames) {
  PuffSequenceOptions o;
  o.frames = frames;
  o.side = 24;
  return o;
}

std::vector<VdbSequenceMember> members_of(const std::vector<std::string>& paths, int first = 1) {
  std::vector<VdbSequenceMember> m;
  for (const std::string& p : paths) m.push_back({p, first++});
  return m;
}

double mean_x(const std::vector<GaussianParticle>& particles) {
  double sum = 0, mass = 0;
  for (const GaussianParticle& p : particles) {
    const double m = -std::log(1.0 - p.density) * p.radius * p.radius;
    sum += m * p.x;
    mass += m;
  }
  return sum / mass;
}

TEST(VdbSequenceImport, ThePuffMovesFromFrameToFrameInOneMedium) {
  const fs::path dir = test::scratch_dir("puff");
  const PuffSequenceOptions puff = small_puff(3);
  const auto members = members_of(write_puff_sequence(dir.string(), puff));
  const fs::path out = dir / "puff.pyroseq";
  fs::create_directories(out);
  check_vdb_sequence_members(members, {});
  VdbSequenceImportReport report;
  const ParticleSequence s = import_vdb_sequence(members, {}, out, nullptr, &report);
  ASSERT_EQ(s.frames.size(), 3u);
  EXPECT_EQ(report.frames, 3u);
  EXPECT_EQ(read_particle_sequence(out.string()).frames.size(), 3u);
  // The generator's centre moves 0.4 of the cube (one world unit) along +x over the sequence:
  // the particles' mass-weighted centre follows it, within a voxel.
  std::vector<double> xs;
  for (const ParticleSequenceFrame& f : s.frames) {
    const ParticleFile file = read_particle_file((out / f.file).string());
    EXPECT_EQ(file.particles.size(), f.particles);
    EXPECT_GT(f.particles, 0u);
    EXPECT_NE(file.metadata_json.find("\"extinction\":" + nlohmann::json(s.extinction).dump()), std::string::npos)
        << file.metadata_json;
    xs.push_back(mean_x(file.particles));
  }
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(xs[k], 0.3 + 0.2 * k, 1.0 / puff.side) << k;
  // The puff grows: more active voxels each frame.
  EXPECT_LT(s.frames[0].active_voxels, s.frames[1].active_voxels);
  EXPECT_LT(s.frames[1].active_voxels, s.frames[2].active_voxels);
}

TEST(VdbSequenceImport, ADamagedMemberIsRefusedByNameBeforeAnyFrameIsRead) {
  const fs::path dir = test::scratch_dir("damaged");
  const auto paths = write_puff_sequence(dir.string(), small_puff(3));
  fs::resize_file(paths[1], fs::file_size(paths[1]) - 100);
  try {
    check_vdb_sequence_members(members_of(paths), {});
    ADD_FAILURE() << "a truncated member was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), paths[1]) << e.what();
  }
  std::ofstream(paths[2], std::ios::trunc) << "not a vdb";
  EXPECT_THROW(check_vdb_sequence_member(paths[2], {}), UserError);
  EXPECT_NO_THROW(check_vdb_sequence_member(paths[0], {}));
  try {
    check_vdb_sequence_member(paths[0], {"temperature", -1});
    ADD_FAILURE() << "a member without the grid was accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("\"density\""), std::string::npos) << e.what();
  }
}

// The OpenUSD test's two frames of one Blender smoke simulation: frame 1 has only empty grids.
TEST(VdbSequenceImport, TheOpenUsdSmokePairImportsWithAnEmptyFirstFrame) {
  const fs::path shared = fs::path(PYRO_SHARED_DATA_DIR) / "vdb";
  if (!fs::is_regular_file(shared / "openusd_smoke_000002.vdb"))
    GTEST_SKIP() << "no third-party VDB files at " PYRO_SHARED_DATA_DIR "/vdb (optional data)";
  const fs::path dir = test::scratch_dir("openusd");
  fs::create_symlink(shared / "openusd_smoke_000001_blender_empty_grids.vdb", dir / "smoke_000001.vdb");
  fs::create_symlink(shared / "openusd_smoke_000002.vdb", dir / "smoke_000002.vdb");
  const auto members = find_vdb_sequence_members((dir / "smoke_%06d.vdb").string());
  ASSERT_EQ(members.size(), 2u);
  check_vdb_sequence_members(members, {});
  const fs::path out = dir / "smoke.pyroseq";
  fs::create_directories(out);
  const ParticleSequence s = import_vdb_sequence(members, {}, out, nullptr);
  EXPECT_EQ(s.frames[0].particles, 0u);
  EXPECT_EQ(s.frames[0].active_voxels, 0u);
  EXPECT_GT(s.frames[1].particles, 0u);
  EXPECT_EQ(s.frames[1].active_voxels, 71983u);
  EXPECT_GT(s.extinction, 0.0);  // chosen from frame 2, the first with active voxels
  EXPECT_EQ(read_particle_file((out / s.frames[0].file).string()).particles.size(), 0u);
}

}  // namespace
}  // namespace pyro
