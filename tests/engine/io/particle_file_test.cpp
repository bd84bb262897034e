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

// The temperature channel: one float32 more per record, last, in either version.
TEST(ParticleFile, TemperatureChannelIsTheRecordsLastFieldInBothVersions) {
  const auto dir = test::scratch_dir("particle_file_temperature");
  ParticleFile v2 = read_particle_file([&] {
    std::string bytes = header(2, 56, 2, "{}");
    append_floats(bytes, two_records());
    write_bytes(dir / "plain.pyrop", bytes);
    return (dir / "plain.pyrop").string();
  }());
  EXPECT_TRUE(v2.temperature.empty());  // files without the channel read as before
  v2.temperature = {1850.0f, 0.25f};
  write_particle_file((dir / "hot2.pyrop").string(), v2);
  std::vector<float> records = two_records();
  records.insert(records.begin() + 14, 1850.0f);
  records.push_back(0.25f);
  std::string want = header(2, 60, 2, "{}");
  append_floats(want, records);
  EXPECT_EQ(test::read_bytes(dir / "hot2.pyrop"), want);
  EXPECT_EQ(read_particle_file((dir / "hot2.pyrop").string()).temperature, v2.temperature);

  std::string v1 = header(1, 36, 1, "{}");
  append_floats(v1, {0, 1, 2, 0.5f, 0.25f, 1, 0.5f, 0.25f, 0.75f});
  write_bytes(dir / "hot1.pyrop", v1);
  const ParticleFile back = read_particle_file((dir / "hot1.pyrop").string());
  ASSERT_EQ(back.particles.size(), 1u);
  EXPECT_EQ(back.particles[0].density, 0.25f);
  EXPECT_EQ(back.temperature, std::vector<float>{0.75f});
  write_particle_file((dir / "again1.pyrop").string(), back);
  EXPECT_EQ(test::read_bytes(dir / "again1.pyrop"), v1);
}

TEST(ParticleFile, BadTemperaturesAreRefusedNamingFileAndParticle) {
  const auto dir = test::scratch_dir("particle_file_bad_temperature");
  std::string bytes = header(1, 36, 2, "{}");
  append_floats(bytes, {0, 1, 2, 0.5f, 0.25f, 1, 0.5f, 0.25f, 1.0f, 0, 1, 2, 0.5f, 0.25f, 1, 0.5f, 0.25f,
                        std::numeric_limits<float>::quiet_NaN()});
  write_bytes(dir / "nan.pyrop", bytes);
  try {
    read_particle_file((dir / "nan.pyrop").string());
    ADD_FAILURE() << "a NaN temperature was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), (dir / "nan.pyrop").string());
    EXPECT_EQ(e.place(), "particle 1");
  }
  ParticleFile f;
  f.particles.resize(2);
  f.temperature = {1.0f};  // one short
  EXPECT_THROW(write_particle_file((dir / "short.pyrop").string(), f), UserError);
  f.temperature = {1.0f, 2e6f};
  EXPECT_THROW(write_particle_file((dir / "big.pyrop").string(), f), UserError);
  EXPECT_FALSE(std::filesystem::exists(dir / "short.pyrop"));
  std::string odd = header(2, 64, 0, "{}");  // neither 56 nor 60
  write_bytes(dir / "odd.pyrop", odd);
  EXPECT_THROW(read_particle_file((dir / "odd.pyrop").string()), UserError);
}

TEST(ParticleFile, RecordedTemperatureMapComesFromTheMetadata) {
  ParticleFile f;
  EXPECT_FALSE(recorded_temperature("f.pyrop", f).has_value());
  f.metadata_json = R"({"temperature": {"grid": "heat", "max": 3.5, "scale": 428.6, "offset": 1000}})";
  const auto r = recorded_temperature("f.pyrop", f);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->grid, "heat");
  EXPECT_DOUBLE_EQ(r->max, 3.5);
  EXPECT_DOUBLE_EQ(r->scale, 428.6);
  EXPECT_DOUBLE_EQ(r->offset, 1000.0);
  EXPECT_DOUBLE_EQ(r->intensity, 4.0);  // written before the exposure was recorded
  f.metadata_json = R"({"temperature": {"grid": "heat", "intensity": 2.75}})";
  EXPECT_DOUBLE_EQ(recorded_temperature("f.pyrop", f)->intensity, 2.75);
  f.metadata_json = R"({"temperature": {"intensity": -1}})";
  try {
    recorded_temperature("f.pyrop", f);
    ADD_FAILURE() << "a negative intensity was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.place(), "metadata/temperature/intensity");
  }
  f.metadata_json = R"({"temperature": {"scale": "hot"}})";
  try {
    recorded_temperature("f.pyrop", f);
    ADD_FAILURE() << "a string scale was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.place(), "metadata/temperature/scale");
  }
}

}  // namespace
}  // namespace pyro
