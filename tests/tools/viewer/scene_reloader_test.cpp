// pyro view's hot reload state machine and the file stamps it compares.
#include "tools/viewer/scene_reloader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

TEST(SceneReloader, StampsChangeWithTheFile) {
  const fs::path dir = test::scratch_dir("stamp");
  const fs::path f = dir / "scene.json";
  EXPECT_FALSE(stamp_file(f.string()).exists);
  { std::ofstream(f) << "{}"; }
  const FileStamp a = stamp_file(f.string());
  EXPECT_TRUE(a.exists);
  EXPECT_EQ(a.size, 2u);
  EXPECT_EQ(stamp_file(f.string()), a);  // nothing changed: the same stamp
  { std::ofstream(f) << "{ }"; }          // in place, one byte longer
  const FileStamp b = stamp_file(f.string());
  EXPECT_NE(b, a);
  // Saved by renaming a new file over it (same size, perhaps the same second): the inode differs.
  { std::ofstream(dir / "new.json") << "{ }"; }
  fs::rename(dir / "new.json", f);
  const FileStamp c = stamp_file(f.string());
  EXPECT_EQ(c.size, b.size);
  EXPECT_NE(c, b);
  fs::remove(f);
  EXPECT_NE(stamp_file(f.string()), c);
}

TEST(SceneReloader, EachStampIsTriedOnceAndAnErrorLastsUntilAGoodLoad) {
  FileStamp loaded{true, 100, 10, 7};
  SceneReloader r(loaded);
  EXPECT_FALSE(r.changed(loaded));
  EXPECT_FALSE(r.showing_error());

  FileStamp broken = loaded;
  broken.mtime_ns = 200;
  ASSERT_TRUE(r.changed(broken));
  r.failed(broken, 5, "scene.json: at line 3, column 1: expected a value");
  EXPECT_TRUE(r.showing_error());
  EXPECT_EQ(r.error(), "scene.json: at line 3, column 1: expected a value");
  EXPECT_FALSE(r.changed(broken));  // the broken file is not loaded again every frame

  FileStamp also_broken = broken;
  also_broken.size = 11;
  ASSERT_TRUE(r.changed(also_broken));
  r.failed(also_broken, 9, "scene.json: at /output/fps: expected a number > 0, found -30");
  EXPECT_EQ(r.error(), "scene.json: at /output/fps: expected a number > 0, found -30");

  FileStamp good = also_broken;
  good.mtime_ns = 300;
  ASSERT_TRUE(r.changed(good));
  r.succeeded(good, 12);
  EXPECT_FALSE(r.showing_error());
  EXPECT_TRUE(r.error().empty());
  ASSERT_EQ(r.history().size(), 3u);
  EXPECT_EQ(r.history()[0].frame, 5u);
  EXPECT_FALSE(r.history()[0].ok);
  EXPECT_EQ(r.history()[1].frame, 9u);
  EXPECT_EQ(r.history()[2].frame, 12u);
  EXPECT_TRUE(r.history()[2].ok);
  EXPECT_TRUE(r.history()[2].error.empty());
}

TEST(SceneReloader, AFailureWithoutAMessageStillShowsAnError) {
  SceneReloader r(FileStamp{});
  r.failed(FileStamp{true, 1, 1, 1}, 0, "");
  EXPECT_TRUE(r.showing_error());
  EXPECT_FALSE(r.error().empty());
}

}  // namespace
}  // namespace pyro
