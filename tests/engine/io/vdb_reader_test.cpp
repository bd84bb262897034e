// The VDB reader: a file written here (always), and the third-party files in ../shared/data/vdb
// (skipped with a message when that folder is absent). Expected figures come from
// ../shared/data/vdb/SOURCES.txt (read there with OpenVDB's own vdb_print), not from our output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "components/volume_medium.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "engine/io/vdb_resampled_volume.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::string shared_vdb(const std::string& name) {
  return (fs::path(PYRO_SHARED_DATA_DIR) / "vdb" / name).string();
}

#define SKIP_WITHOUT_SHARED_VDB()                                                          \
  if (!fs::is_directory(fs::path(PYRO_SHARED_DATA_DIR) / "vdb"))                           \
  GTEST_SKIP() << "no third-party VDB files at " PYRO_SHARED_DATA_DIR "/vdb (optional data)"

std::string expect_user_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no UserError";
  return "";
}

TEST(VdbReader, RoundTripsAFogVolumeWithItsTransform) {
  const fs::path dir = test::scratch_dir("vdb_roundtrip");
  const std::string path = (dir / "box.vdb").string();
  std::vector<float> v(4 * 3 * 2, 0.0f);
  v[0] = 0.5f;
  v[23] = 1.25f;
  write_vdb_fog_volume(path, "density", {10, 20, 30}, {4, 3, 2}, v, 0.25, {1.0, 2.0, 3.0});
  const auto grids = list_vdb_grids(path);
  ASSERT_EQ(grids.size(), 1u);
  EXPECT_EQ(grids[0].value_type, "float");
  EXPECT_EQ(grids[0].grid_class, "fog volume");
  EXPECT_EQ(grids[0].active_voxels, 2u);
  const DenseGrid g = read_vdb_grid(path);
  EXPECT_EQ(g.origin, (std::array<int, 3>{10, 20, 30}));
  EXPECT_EQ(g.dims, (std::array<int, 3>{4, 3, 2}));
  EXPECT_FLOAT_EQ(g.at(0, 0, 0), 0.5f);
  EXPECT_FLOAT_EQ(g.at(3, 2, 1), 1.25f);
  // index (10, 20, 30) -> world 0.25 * (10, 20, 30) + (1, 2, 3)
  const glm::dvec4 w = g.index_to_world * glm::dvec4(10, 20, 30, 1);
  EXPECT_NEAR(w.x, 3.5, 1e-12);
  EXPECT_NEAR(w.y, 7.0, 1e-12);
  EXPECT_NEAR(w.z, 10.5, 1e-12);
}

TEST(VdbReader, RefusesMissingAndTruncatedFiles) {
  const fs::path dir = test::scratch_dir("vdb_truncated");
  EXPECT_NE(expect_user_error([&] { list_vdb_grids((dir / "absent.vdb").string()); }).find("No such file"),
            std::string::npos);
  const std::string path = (dir / "box.vdb").string();
  std::vector<float> v(8 * 8 * 8, 0.3f);
  write_vdb_fog_volume(path, "density", {0, 0, 0}, {8, 8, 8}, v, 1.0, {0, 0, 0});
  const auto size = fs::file_size(path);
  for (double frac : {0.01, 0.3, 0.9, 0.999}) {
    fs::copy_file(path, dir / "cut.vdb", fs::copy_options::overwrite_existing);
    fs::resize_file(dir / "cut.vdb", uintmax_t(size * frac));
    const std::string msg = expect_user_error([&] { read_vdb_grid((dir / "cut.vdb").string()); });
    EXPECT_FALSE(msg.empty()) << frac;
  }
}

TEST(VdbReader, ThirdPartyFilesImportOrAreRefusedWithAReason) {
  SKIP_WITHOUT_SHARED_VDB();
  {
    const DenseGrid g = read_vdb_grid(shared_vdb("wdas_cloud_sixteenth.vdb"));
    EXPECT_EQ(g.active_voxels, 415642u);
    EXPECT_EQ(g.dims, (std::array<int, 3>{126, 86, 154}));  // bbox (-66,-21,-90)->(59,64,63)
    EXPECT_NEAR(g.voxel_size[0], 3.333, 1e-3);
  }
  {
    const DenseGrid g = read_vdb_grid(shared_vdb("openvdb_sample_smoke1.vdb"));
    EXPECT_TRUE(g.half_float);
    EXPECT_EQ(g.active_voxels, 1049275u);
    EXPECT_NEAR(g.max_value, 5.71, 0.01);
  }
  {
    std::string note;
    const DenseGrid g = read_vdb_grid(shared_vdb("openvdb_sample_sphere_levelset.vdb"), {}, &note);
    EXPECT_TRUE(g.converted_from_level_set);
    EXPECT_NE(note.find("ls_sphere"), std::string::npos);
    EXPECT_FLOAT_EQ(g.max_value, 1.0f);  // fog: 1 inside
  }
  {
    const DenseGrid g = read_vdb_grid(shared_vdb("openusd_smoke_000002.vdb"));
    EXPECT_NEAR(g.voxel_size[0], 0.1326, 1e-4);  // non-uniform
    EXPECT_NEAR(g.voxel_size[2], 0.1317, 1e-4);
    EXPECT_EQ(g.active_voxels, 71983u);
  }
  // Repeated names: chosen by index.
  EXPECT_EQ(read_vdb_grid(shared_vdb("arnoldusd_grids_3x_density.vdb"), {"", 1}).active_voxels, 2222u);
  EXPECT_EQ(read_vdb_grid(shared_vdb("arnoldusd_grids_3x_density.vdb"), {"", 2}).active_voxels, 803u);
  EXPECT_TRUE(read_vdb_grid(shared_vdb("openusd_smoke_000001_blender_empty_grids.vdb")).empty());
  EXPECT_EQ(read_vdb_grid(shared_vdb("openusd_densityAndHeat.vdb"), {"heat", -1}).active_voxels, 5224u);
  // Vector and point grids: refused, and the message lists what the file holds.
  std::string msg = expect_user_error([] { read_vdb_grid(shared_vdb("zeno_vel_VDB_bound_v02.vdb")); });
  EXPECT_NE(msg.find("\"vel\" vec3s"), std::string::npos) << msg;
  msg = expect_user_error([] { read_vdb_grid(shared_vdb("gaffer_points.vdb")); });
  EXPECT_NE(msg.find("ptdataidx32"), std::string::npos) << msg;
  msg = expect_user_error(
      [] { read_vdb_grid(shared_vdb("openusd_smoke_000001_blender_empty_grids.vdb"), {"obstacles", -1}); });
  EXPECT_NE(msg.find("int32"), std::string::npos) << msg;
}

TEST(VdbReader, TruncatedCopiesOfEveryThirdPartyFileAreRefused) {
  SKIP_WITHOUT_SHARED_VDB();
  const fs::path dir = test::scratch_dir("vdb_shared_truncated");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PYRO_SHARED_DATA_DIR) / "vdb")) {
    if (entry.path().extension() != ".vdb") continue;
    ++files;
    const auto size = fs::file_size(entry.path());
    for (double frac : {0.05, 0.5, 0.995}) {
      fs::copy_file(entry.path(), dir / "cut.vdb", fs::copy_options::overwrite_existing);
      fs::resize_file(dir / "cut.vdb", uintmax_t(size * frac));
      EXPECT_FALSE(expect_user_error([&] { read_vdb_grid((dir / "cut.vdb").string()); }).empty())
          << entry.path() << " cut at " << frac;
    }
  }
  EXPECT_GT(files, 0) << "no .vdb file in " PYRO_SHARED_DATA_DIR "/vdb";
}

TEST(ImportVdbCli, TruncatedFileExitsTwoAndWritesNothing) {
  const fs::path dir = test::scratch_dir("vdb_cli_truncated");
  const std::string path = (dir / "box.vdb").string();
  std::vector<float> v(8 * 8 * 8, 0.3f);
  write_vdb_fog_volume(path, "density", {0, 0, 0}, {8, 8, 8}, v, 1.0, {0, 0, 0});
  fs::resize_file(path, fs::file_size(path) / 2);
  const fs::path out = dir / "out.pyrop";
  const auto r = test::run_pyro({"import-vdb", path, "--out", out.string(), "--json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
}

TEST(ImportVdbCli, SmallVolumeImportsAndTheParticleFileReadsBack) {
  const fs::path dir = test::scratch_dir("vdb_cli_import");
  const std::string path = (dir / "blob.vdb").string();
  const int n = 16;
  std::vector<float> v(n * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double d2 = (x - 7.5) * (x - 7.5) + (y - 7.5) * (y - 7.5) + (z - 7.5) * (z - 7.5);
        v[(z * n + y) * n + x] = d2 < 49 ? float(1.0 - d2 / 49) : 0.0f;
      }
  write_vdb_fog_volume(path, "density", {0, 0, 0}, {n, n, n}, v, 0.5, {0, 0, 0});
  const fs::path out = dir / "blob.pyrop";
  const auto r = test::run_pyro({"import-vdb", path, "--out", out.string(), "--json", "--width", "48", "--height", "48"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const ParticleFile f = read_particle_file(out.string());
  EXPECT_EQ(f.version, 2u);  // fitted anisotropic particles
  EXPECT_EQ(j["particles"].get<size_t>(), f.anisotropic.size());
  EXPECT_GT(f.anisotropic.size(), 0u);
  EXPECT_LE(j["rmse"].get<double>(), 0.03);
  // The error from every side, and whether the target was met.
  EXPECT_EQ(j["views"], 7);
  EXPECT_EQ(j["view_rmse"].size(), 7u);
  EXPECT_EQ(j["error_target"], 0.03);
  EXPECT_EQ(j["target_met"].get<bool>(), j["rmse_views_max"].get<double>() <= 0.03);
  EXPECT_GE(j["rmse_views_max"].get<double>(), j["rmse_views_mean"].get<double>());
  // What relighting needs beside each particle's extinction: the medium's albedo, recorded.
  EXPECT_EQ(nlohmann::json::parse(f.metadata_json)["albedo"], j["albedo"]);
  EXPECT_DOUBLE_EQ(imported_albedo(out.string(), f), VolumeMedium{}.albedo);
  // A target it cannot reach is said on stderr and in the JSON, and the file is still written.
  const fs::path strict_out = dir / "strict.pyrop";
  const auto strict = test::run_pyro({"import-vdb", path, "--out", strict_out.string(), "--json", "--width",
                                      "48", "--height", "48", "--error", "0.00001"});
  ASSERT_EQ(strict.exit_code, 0) << strict.err;
  const auto s = nlohmann::json::parse(strict.out);
  EXPECT_FALSE(s["target_met"].get<bool>());
  EXPECT_FALSE(s["reason"].get<std::string>().empty());
  EXPECT_NE(strict.err.find("not met"), std::string::npos) << strict.err;
  EXPECT_TRUE(fs::exists(strict_out));
  // A truncated particle file is refused.
  fs::resize_file(out, fs::file_size(out) - 4);
  EXPECT_FALSE(expect_user_error([&] { read_particle_file(out.string()); }).empty());
}

// A grid whose box is too large for a dense copy (two clumps 1.1e6 voxels apart, a box of
// 2.9e8 voxels) cannot be fitted: it is imported sparse by the octree, says so, and is measured
// from the seven views against the path-traced truth of its bricks.
TEST(ImportVdbCli, ABoxTooLargeForTheDenseReferenceIsMeasuredAgainstThePathTracedTruth) {
  DenseGrid src;
  src.dims = {140000, 1, 1};
  src.values.assign(140000, 0.0f);
  src.values.front() = src.values.back() = 0.5f;
  const fs::path dir = test::scratch_dir("vdb_cli_large_box");
  const std::string path = (dir / "far.vdb").string();
  write_vdb_resampled_fog_volume(path, "density", src, 8.0);
  const fs::path out = dir / "far.pyrop";
  const auto r = test::run_pyro(
      {"import-vdb", path, "--out", out.string(), "--json", "--width", "32", "--height", "32", "--samples", "8"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["measured"].get<bool>());
  EXPECT_EQ(j["views"], 7);
  EXPECT_EQ(j["view_rmse"].size(), 7u);
  EXPECT_EQ(j["view_noise"].size(), 7u);
  EXPECT_EQ(j["target_met"].get<bool>(), j["rmse_views_max_without_noise"].get<double>() <= 0.03);
  EXPECT_LE(j["rmse_views_max_without_noise"].get<double>(), j["rmse_views_max"].get<double>());
  EXPECT_NE(j["reason"].get<std::string>().find("path traced"), std::string::npos);
  EXPECT_NE(r.err.find("path traced"), std::string::npos) << r.err;
  EXPECT_EQ(j["active_voxels"].get<uint64_t>(), 2u * 16u * 16u * 16u);
  const ParticleFile f = read_particle_file(out.string());
  EXPECT_EQ(f.version, 1u);
  EXPECT_EQ(f.particles.size(), j["particles"].get<size_t>());
  EXPECT_GT(f.particles.size(), 0u);
}

}  // namespace
}  // namespace pyro
