// The installed package finds its installed content, not the source tree it was built from:
// the content folder is the package's share/pyrocumulus (Pyrocumulus_CONTENT_DIR, from the
// package config), it holds the shaders and scenes, and the default flame flipbook is there.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "engine/core/content_location.h"
#include "engine/core/content_path.h"

namespace {

namespace fs = std::filesystem;

TEST(ConsumerContent, TheInstalledEngineReadsTheInstalledContent) {
  ASSERT_EQ(std::getenv("PYRO_CONTENT_DIR"), nullptr) << "run without PYRO_CONTENT_DIR";
  EXPECT_EQ(fs::path(pyro::content_dir()), fs::path(PYROCUMULUS_CONTENT_DIR));
  EXPECT_TRUE(fs::is_regular_file(pyro::content_path("shaders/billboard.vert")));
  EXPECT_TRUE(fs::is_regular_file(pyro::content_path("scenes/fog.json")));
  EXPECT_TRUE(fs::is_regular_file(fs::path(pyro::built_in_flipbook_dir()) / "flipbook.json"));
  EXPECT_EQ(fs::path(pyro::built_in_flipbook_dir()),
            fs::path(PYROCUMULUS_CONTENT_DIR) / "flipbooks" / "fire");
}

TEST(ConsumerContent, PyroContentDirStillOverridesIt) {
  ::setenv("PYRO_CONTENT_DIR", "/elsewhere", 1);
  EXPECT_EQ(pyro::content_dir(), "/elsewhere");
  ::unsetenv("PYRO_CONTENT_DIR");
  EXPECT_EQ(fs::path(pyro::content_dir()), fs::path(PYROCUMULUS_CONTENT_DIR));
}

}  // namespace
