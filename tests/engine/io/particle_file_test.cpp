// Particle files (engine/io/particle_file.h, docs/particle_format.md): version 2 holds anisotropic
// particles as 14 float32 each in the documented order and round-trips; version 1 files, written
// by hand from the documented layout, still read; truncated files and bad values are refused with
// the file and the particle named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "tests/support/file_bytes.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

std::string header(uint32_t version, uint32_t record, uint64_t count, const std::string& meta) {
  std::string s = "PYROPTCL";
  s.append(reinterpret_cast<const char*>(&version), 4);
  s.append(reinterpret_cast<const char*>(&record), 4);
  s.append(reinterpret_cast<const char*>(&count), 8);
  const uint32_t m = uint32_t(meta.size());
  s.append(reinterpret_cast<const char*>(&m), 4);
  return s + meta;
}

void append_floats(std::string& s, const std::vector<float>& v) {
  s.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
}

void write_bytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// Two valid version 2 records: centre, rotation wxyz, scale, extinction, rgb.
std::vector<float> two_records() {
  return {1, 2, 3, 0.5f, 0.5f, -0.5f, 0.5f, 0.1f, 0.2f, 0.3f, 4.0f, 0.9f, 0.8f, 0.7f,
          -1, 0, 0.25f, 1, 0, 0, 0, 1.5f, 0.5f, 0.75f, 0.0f, 0.1f, 0.2f, 0.3f};
}

TEST(ParticleFile, AnisotropicRoundTripInTheDocumentedLayout) {
  const auto dir = test::scratch_dir("particle_file_v2");
  ParticleFile f;
  f.metadata_json = R"({"source": "test"})";
  AnisotropicGaussian g;
  g.centre = {1, 2, 3};
  g.rotation = glm::quat(0.5f, 0.5f, -0.5f, 0.5f);
  g.scale = {0.1f, 0.2f, 0.3f};
  g.extinction = 4.0f;
  g.color = {0.9f, 0.8f, 0.7f};
  f.anisotropic = {g, g};
  f.anisotropic[1].centre = {-1, 0, 0.25f};
  f.anisotropic[1].rotation = glm::quat(1, 0, 0, 0);
  f.anisotropic[1].scale = {1.5f, 0.5f, 0.75f};
  f.anisotropic[1].extinction = 0.0f;
  f.anisotropic[1].color = {0.1f, 0.2f, 0.3f};
  const std::string path = (dir / "two.pyrop").string();
  write_particle_file(path, f);
  std::string want = header(2, 56, 2, f.metadata_json);
  append_floats(want, two_records());
  EXPECT_EQ(test::read_bytes(path), want);
  const ParticleFile back = read_particle_file(path);
  EXPECT_EQ(back.version, 2u);
  EXPECT_TRUE(back.particles.empty());
  EXPECT_EQ(back.metadata_json, f.metadata_json);
  ASSERT_EQ(back.anisotropic.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const AnisotropicGaussian &a = back.anisotropic[i], &b = f.anisotropic[i];
    EXPECT_EQ(a.centre, b.centre);
    EXPECT_EQ(a.rotation, b.rotation);
    EXPECT_EQ(a.scale, b.scale);
    EXPECT_EQ(a.extinction, b.extinction);
    EXPECT_EQ(a.color, b.color);
  }
}

TEST(ParticleFile, VersionOneWrittenByHandStillReads) {
  const auto dir = test::scratch_dir("particle_file_v1");
  std::string bytes = header(1, 32, 2, "{}");
  append_floats(bytes, {0, 1, 2, 0.5f, 0.25f, 1, 0.5f, 0.25f, -3, 4, 5, 2.0f, 0.0f, 0.1f, 0.2f, 0.3f});
  const auto path = dir / "v1.pyrop";
  write_bytes(path, bytes);
  const ParticleFile f = read_particle_file(path.string());
  EXPECT_EQ(f.version, 1u);
  EXPECT_TRUE(f.anisotropic.empty());
  ASSERT_EQ(f.particles.size(), 2u);
  EXPECT_EQ(f.particles[1].x, -3.0f);
  EXPECT_EQ(f.particles[1].radius, 2.0f);
  EXPECT_EQ(f.particles[0].density, 0.25f);
  // Written again it is the same version 1 file.
  const auto again = dir / "again.pyrop";
  write_particle_file(again.string(), f);
  EXPECT_EQ(test::read_bytes(again), bytes);
}

TEST(ParticleFile, EmptyFilesKeepTheirVersionAndKindsDoNotMix) {
  const auto dir = test::scratch_dir("particle_file_kinds");
  ParticleFile f;
  f.version = 2;
  write_particle_file((dir / "empty.pyrop").string(), f);
  EXPECT_EQ(read_particle_file((dir / "empty.pyrop").string()).version, 2u);
  f.particles.push_back(GaussianParticle{});
  EXPECT_THROW(write_particle_file((dir / "bad.pyrop").string(), f), UserError);  // v2, isotropic
  f.version = 0;
  f.anisotropic.push_back(AnisotropicGaussian{});
  EXPECT_THROW(write_particle_file((dir / "bad.pyrop").string(), f), UserError);  // both kinds
}

TEST(ParticleFile, TruncatedOrPaddedVersionTwoIsRefused) {
  const auto dir = test::scratch_dir("particle_file_truncated");
  std::string bytes = header(2, 56, 2, "{}");
  append_floats(bytes, two_records());
  const auto path = dir / "t.pyrop";
  for (const std::string& b : {bytes.substr(0, bytes.size() - 1), bytes + "x", bytes.substr(0, 20)}) {
    write_bytes(path, b);
    try {
      read_particle_file(path.string());
      ADD_FAILURE() << "accepted " << b.size() << " bytes";
    } catch (const UserError& e) {
      EXPECT_EQ(e.file(), path.string());
    }
  }
  // A version 2 header with version 1's record size.
  std::string wrong = header(2, 32, 1, "{}");
  append_floats(wrong, {0, 0, 0, 1, 0.5f, 1, 1, 1});
  write_bytes(path, wrong);
  EXPECT_THROW(read_particle_file(path.string()), UserError);
}

TEST(ParticleFile, EveryBadValueIsRefusedNamingTheParticle) {
  const auto dir = test::scratch_dir("particle_file_values");
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  // (field index in the record, bad value): each is put into the second particle.
  const std::vector<std::pair<int, float>> bad = {
      {0, nan}, {2, inf}, {3, nan}, {7, 0.0f}, {8, -0.1f}, {9, inf}, {10, -1.0f}, {10, nan}, {13, -inf}};
  const auto path = dir / "bad.pyrop";
  for (const auto& [field, value] : bad) {
    std::vector<float> records = two_records();
    records[14 + field] = value;
    std::string bytes = header(2, 56, 2, "{}");
    append_floats(bytes, records);
    write_bytes(path, bytes);
    try {
      read_particle_file(path.string());
      ADD_FAILURE() << "accepted field " << field << " = " << value;
    } catch (const UserError& e) {
      EXPECT_EQ(e.file(), path.string());
      EXPECT_EQ(e.place(), "particle 1") << field;
    }
  }
  // The zero quaternion; a tiny one is still a rotation.
  std::vector<float> records = two_records();
  for (int k = 3; k < 7; ++k) records[14 + k] = 0.0f;
  std::string bytes = header(2, 56, 2, "{}");
  append_floats(bytes, records);
  write_bytes(path, bytes);
  EXPECT_THROW(read_particle_file(path.string()), UserError);
  records[14 + 4] = 1e-30f;
  bytes = header(2, 56, 2, "{}");
  append_floats(bytes, records);
  write_bytes(path, bytes);
  EXPECT_EQ(read_particle_file(path.string()).anisotropic.size(), 2u);
}

// The albedo a lit scene relights an import with: the metadata's, else the one every import was
// made with before it was recorded; malformed metadata is refused by name.
TEST(ParticleFile, TheImportedAlbedoComesFromTheMetadata) {
  ParticleFile f;
  f.metadata_json = R"({"source": "a.vdb", "albedo": 0.7})";
  EXPECT_DOUBLE_EQ(imported_albedo("a.pyrop", f), 0.7);
  f.metadata_json = R"({"source": "a.vdb"})";
  EXPECT_DOUBLE_EQ(imported_albedo("a.pyrop", f), kImportAlbedoBeforeRecorded);
  for (const char* bad : {R"({"albedo": 1.5})", R"({"albedo": "grey"})", R"({"albedo": -0.1})"}) {
    f.metadata_json = bad;
    try {
      imported_albedo("a.pyrop", f);
      ADD_FAILURE() << bad;
    } catch (const UserError& e) {
      EXPECT_NE(std::string(e.what()).find("metadata/albedo"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("a.pyrop"), std::string::npos) << e.what();
    }
  }
  f.metadata_json = "not json";
  EXPECT_THROW(imported_albedo("a.pyrop", f), UserError);
}

}  // namespace
}  // namespace pyro
