#include "engine/io/scratch_folder.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pyro {
namespace {

namespace fs = std::filesystem;

// Two folders of one prefix are distinct, under the temporary folder, and each goes with
// everything in it when its owner does.
TEST(ScratchFolder, IsFreshAndGoesWithItsContents) {
  fs::path first, second;
  {
    const ScratchFolder a("pyro-scratch-test"), b("pyro-scratch-test");
    first = a.path;
    second = b.path;
    EXPECT_NE(first, second);
    EXPECT_TRUE(fs::is_directory(first));
    EXPECT_EQ(first.parent_path(), fs::temp_directory_path());
    EXPECT_EQ(first.filename().string().rfind("pyro-scratch-test-", 0), 0u);
    fs::create_directories(first / "inner");
    std::ofstream(first / "inner" / "file.txt") << "x";
  }
  EXPECT_FALSE(fs::exists(first));
  EXPECT_FALSE(fs::exists(second));
}

}  // namespace
}  // namespace pyro
