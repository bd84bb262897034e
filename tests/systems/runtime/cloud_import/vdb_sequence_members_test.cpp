// The members of an animated VDB sequence (systems/runtime/cloud_import/vdb_sequence_members.h): found
// from a printf pattern, a glob or a folder, in natural frame order, with gaps, duplicates and
// empty matches refused naming the file.
#include <gtest/gtest.h>

#include <fstream>

#include "engine/core/user_error.h"
#include "systems/runtime/cloud_import/vdb_sequence_members.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& p) { std::ofstream(p) << "x"; }

std::vector<int64_t> frames_of(const std::vector<VdbSequenceMember>& m) {
  std::vector<int64_t> f;
  for (const VdbSequenceMember& x : m) f.push_back(x.frame);
  return f;
}

std::string error_of_vdb_sequence_members(const std::string& input) {
  try {
    find_vdb_sequence_members(input);
  } catch (const UserError& e) {
    return e.what();
  }
  return "no error";
}

TEST(VdbSequenceMembers, PrintfPatternMatchesItsOwnWidthOnly) {
  const fs::path dir = test::scratch_dir("printf");
  for (const char* n : {"smoke_000009.vdb", "smoke_000010.vdb", "smoke_000011.vdb", "smoke_11.vdb", "smoke_x.vdb"})
    touch(dir / n);
  const std::string pattern = (dir / "smoke_%06d.vdb").string();
  EXPECT_TRUE(names_vdb_sequence(pattern));
  const auto m = find_vdb_sequence_members(pattern);
  EXPECT_EQ(frames_of(m), (std::vector<int64_t>{9, 10, 11}));
  EXPECT_EQ(m[1].path, (dir / "smoke_000010.vdb").string());
}

TEST(VdbSequenceMembers, GlobAndFolderSortNaturallyByFrameNumber) {
  const fs::path dir = test::scratch_dir("glob");
  for (const char* n : {"s_10.vdb", "s_8.vdb", "s_9.vdb", "notes.txt"}) touch(dir / n);
  const auto glob = find_vdb_sequence_members((dir / "s_*.vdb").string());
  EXPECT_EQ(frames_of(glob), (std::vector<int64_t>{8, 9, 10}));
  EXPECT_EQ(fs::path(glob[2].path).filename(), "s_10.vdb");
  EXPECT_TRUE(names_vdb_sequence(dir.string()));
  EXPECT_EQ(frames_of(find_vdb_sequence_members(dir.string())), (std::vector<int64_t>{8, 9, 10}));
  EXPECT_FALSE(names_vdb_sequence((dir / "s_8.vdb").string()));
}

TEST(VdbSequenceMembers, AGapIsRefusedNamingTheMissingFile) {
  const fs::path dir = test::scratch_dir("gap");
  for (const char* n : {"smoke_0001.vdb", "smoke_0002.vdb", "smoke_0004.vdb"}) touch(dir / n);
  for (const std::string& input : {(dir / "smoke_%04d.vdb").string(), (dir / "smoke_*.vdb").string(), dir.string()}) {
    const std::string e = error_of_vdb_sequence_members(input);
    EXPECT_NE(e.find((dir / "smoke_0003.vdb").string()), std::string::npos) << input << ": " << e;
    EXPECT_NE(e.find("frame 3"), std::string::npos) << e;
  }
}

TEST(VdbSequenceMembers, NothingMatchingDuplicatesAndUnnumberedNamesAreRefused) {
  const fs::path dir = test::scratch_dir("refused");
  EXPECT_NE(error_of_vdb_sequence_members((dir / "none_%04d.vdb").string()).find("found none matching the pattern"), std::string::npos);
  EXPECT_NE(error_of_vdb_sequence_members((dir / "missing" / "a_*.vdb").string()).find("no folder"), std::string::npos);
  touch(dir / "a_1.vdb");
  touch(dir / "a_01.vdb");
  EXPECT_NE(error_of_vdb_sequence_members((dir / "a_*.vdb").string()).find("both numbered 1"), std::string::npos);
  const fs::path other = test::scratch_dir("unnumbered");
  touch(other / "cloud.vdb");
  EXPECT_NE(error_of_vdb_sequence_members(other.string()).find("no frame number"), std::string::npos);
}

}  // namespace
}  // namespace pyro
