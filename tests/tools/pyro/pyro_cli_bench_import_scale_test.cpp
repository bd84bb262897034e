// pyro bench import-scale end to end on a small file: one JSON object whose figures hang together
// (voxels per second from the active voxels and the two times, the peak memory of both
// processes), the file written then reused with --keep, deleted without it, and the resampled
// source said on stderr.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/file_bytes.h"
#include "tests/support/json_output.h"
#include "tests/support/scratch_mount.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

TEST(PyroCliBenchImportScale, ReportsVoxelsPerSecondAndPeakMemory) {
  const fs::path dir = test::scratch_dir("bench_import_scale");
  const std::string keep = (dir / "synthetic.vdb").string();
  const auto first = test::run_pyro({"bench", "import-scale", "--voxels", "200000", "--keep", keep, "--json"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.err.find("resampled"), std::string::npos) << first.err;
  const nlohmann::json r = test::last_json_line(first.out);
  EXPECT_TRUE(r["generated"].get<bool>());
  EXPECT_GE(r["active_voxels"].get<uint64_t>(), 200000u);
  EXPECT_LT(r["active_voxels"].get<uint64_t>(), 400000u);
  EXPECT_GT(r["particles"].get<uint64_t>(), 0u);
  const double seconds = r["read_seconds"].get<double>() + r["import_seconds"].get<double>();
  EXPECT_NEAR(r["voxels_per_second"].get<double>(), r["active_voxels"].get<double>() / seconds,
              1e-6 * r["voxels_per_second"].get<double>());
  EXPECT_GT(r["parent_peak_rss_bytes"].get<uint64_t>(), 0u);
  EXPECT_GT(r["child_peak_rss_bytes"].get<uint64_t>(), 0u);
  EXPECT_EQ(r["peak_rss_bytes"].get<uint64_t>(),
            std::max(r["parent_peak_rss_bytes"].get<uint64_t>(), r["child_peak_rss_bytes"].get<uint64_t>()));
  EXPECT_GE(r["bricks"].get<uint64_t>() * 512, r["active_voxels"].get<uint64_t>());
  EXPECT_EQ(r["file_bytes"].get<uint64_t>(), fs::file_size(keep));
  // The import's error against the path-traced truth of the sparse grid: within the import's
  // target beside the truth's own noise.
  ASSERT_TRUE(r["measured"].get<bool>());
  EXPECT_LT(r["reference_monte_carlo_error"].get<double>(), 0.03);
  EXPECT_LE(r["rmse_vs_reference"].get<double>(), 0.03 + r["reference_monte_carlo_error"].get<double>());
  EXPECT_GT(r["rmse_vs_reference"].get<double>(), 0.0);

  // Kept, then reused: the same grid, the same particles.
  const auto again = test::run_pyro({"bench", "import-scale", "--keep", keep, "--json"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const nlohmann::json s = test::last_json_line(again.out);
  EXPECT_FALSE(s["generated"].get<bool>());
  EXPECT_EQ(s["active_voxels"], r["active_voxels"]);
  EXPECT_EQ(s["particles"], r["particles"]);

  // Without --keep, the file lives in a temporary folder and is gone afterwards; as text.
  const auto text = test::run_pyro({"bench", "import-scale", "--voxels", "20000"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("active voxels/s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("peak resident memory"), std::string::npos) << text.out;
}

// A kept file is validated like any input: one that is damaged or cut short (a full disk, a
// killed writer) is discarded with a note and written again, never read as if whole.
TEST(PyroCliBenchImportScale, ADamagedOrTruncatedKeptFileIsDiscardedAndWrittenAgain) {
  const fs::path dir = test::scratch_dir("bench_import_scale_damaged");
  const std::string keep = (dir / "bad.vdb").string();
  { std::FILE* f = std::fopen(keep.c_str(), "wb"); std::fputs("not a vdb file", f); std::fclose(f); }
  const auto r = test::run_pyro({"bench", "import-scale", "--voxels", "20000", "--keep", keep, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("discarding the kept file"), std::string::npos) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(r.out).at("generated").get<bool>());
  // Cut the now valid file short: the next run discards it too.
  const auto size = fs::file_size(keep);
  fs::resize_file(keep, size / 2);
  const auto again = test::run_pyro({"bench", "import-scale", "--voxels", "20000", "--keep", keep, "--json"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("discarding the kept file"), std::string::npos) << again.err;
  EXPECT_TRUE(nlohmann::json::parse(again.out).at("generated").get<bool>());
  EXPECT_EQ(fs::file_size(keep), size);
}

// A full disk while the kept file is written: OpenVDB's writer sees no error, the check of the
// written file does; status 1 naming the OS error, and nothing is moved into place.
TEST(PyroCliBenchImportScale, AFullDiskLeavesNoTruncatedKeptFile) {
  const fs::path dir = test::scratch_dir("bench_import_scale_full_disk");
  test::ScratchMount disk(dir / "disk", "size=300k");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  const std::string keep = (disk.dir() / "kept.vdb").string();
  const auto r = test::run_pyro({"bench", "import-scale", "--voxels", "200000", "--keep", keep});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(disk.dir())) << "no truncated file, no temporary file";
}

TEST(PyroCliBenchImportScale, KeepOverTheSourceIsRefusedBeforeAnyWork) {
  const fs::path dir = test::scratch_dir("bench_import_scale_keep_source");
  const fs::path source = dir / "source.vdb";
  fs::copy_file(content_path("volumes/sample_cloud.vdb"), source);
  const std::string before = test::read_bytes(source);
  const auto r = test::run_pyro({"bench", "import-scale", "--voxels", "20000", "--source", source.string(),
                                 "--keep", source.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--keep"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("writing"), std::string::npos) << "refused before the work: " << r.err;
  EXPECT_EQ(test::read_bytes(source), before);
}

}  // namespace
}  // namespace pyro
