// StagingFolder: files appear in the output folder only on commit(); otherwise nothing is left.
// The staging folder lives inside the output folder (same file system).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/io/staging_folder.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(StagingFolder, WithoutCommitNothingIsLeft) {
  const fs::path dir = test::scratch_dir("staging_abandon");
  const fs::path out = dir / "frames";
  {
    StagingFolder staging(out.string());
    EXPECT_EQ(staging.path().parent_path(), fs::absolute(out).lexically_normal());
    std::ofstream(staging.path() / "frame_0000.png") << "partial";
    EXPECT_EQ(entries(dir), 1u);  // `out`, made for the staging folder
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(entries(dir), 0u);
}

TEST(StagingFolder, CommitMovesEveryFileAndKeepsOtherFiles) {
  const fs::path dir = test::scratch_dir("staging_commit");
  const fs::path out = dir / "frames";
  fs::create_directories(out);
  std::ofstream(out / "frame_0000.png") << "old";
  std::ofstream(out / "notes.txt") << "keep";
  {
    StagingFolder staging(out.string() + "/");  // a trailing separator names the same folder
    std::ofstream(staging.path() / "frame_0000.png") << "new0";
    std::ofstream(staging.path() / "frame_0001.png") << "new1";
    staging.commit();
  }
  EXPECT_EQ(entries(dir), 1u);  // only `frames`
  EXPECT_EQ(entries(out), 3u);  // and no staging folder left inside it
  std::ifstream f0(out / "frame_0000.png");
  std::string text;
  f0 >> text;
  EXPECT_EQ(text, "new0");
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
}

TEST(StagingFolder, OwnerIsTheProcessIdTheNameEndsWith) {
  EXPECT_EQ(staging_owner(".partial-4242"), 4242);
  EXPECT_EQ(staging_owner(".frames.partial-17"), 17);
  EXPECT_EQ(staging_owner("frame_0000.png"), 0);
  EXPECT_EQ(staging_owner(".partial-"), 0);
  EXPECT_EQ(staging_owner(".partial-12x"), 0);
  EXPECT_EQ(staging_owner("partial-12"), 0) << "only hidden names are staging folders";
}

}  // namespace
}  // namespace pyro
