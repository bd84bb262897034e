// Fault injection end to end: a full disk, a read-only file system and a mount point as --out
// (tmpfs mounts: needs root, as in CI; skipped with a message otherwise), two runs into one
// folder, a folder holding another scene's frames, staging folders left by killed runs.
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "tests/support/cli_render.h"
#include "tests/support/scratch_mount.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

using test::contents;
using test::read_bytes;
using test::render;

bool is_complete_png(const std::string& bytes) {
  return bytes.size() > 20 && bytes.compare(0, 4, "\x89PNG") == 0 &&
         bytes.compare(bytes.size() - 8, 4, "IEND") == 0;
}

TEST(PyroCliFault, FullDiskFailsKeepingEarlierFramesAndLeavingNothingPartial) {
  const fs::path dir = test::scratch_dir("full_disk");
  test::ScratchMount disk(dir / "disk", "size=200k");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  const fs::path out = disk.dir() / "out";
  const auto first = render("fog.json", out, "0:1", 256);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const auto before = contents(out);
  ASSERT_EQ(before.size(), 3u);  // two frames and the manifest
  for (const char* f : {"frame_0000.png", "frame_0001.png"}) EXPECT_TRUE(is_complete_png(before.at(f)));

  const auto r = render("fog.json", out, "20", 256);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(".png"), std::string::npos) << "names the file: " << r.err;
  EXPECT_EQ(r.out.find("rendered"), std::string::npos) << "no success summary: " << r.out;
  EXPECT_EQ(contents(out), before) << "the earlier frames, byte for byte, and nothing else";
  EXPECT_EQ(contents(disk.dir()).size(), 1u) << "nothing beside the folder either";
}

TEST(PyroCliFault, ReadOnlyFileSystemFailsNamingTheErrorAndKeepsTheFolder) {
  const fs::path dir = test::scratch_dir("read_only");
  test::ScratchMount disk(dir / "disk", "size=4m");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  const fs::path out = disk.dir() / "out";
  ASSERT_EQ(render("fog.json", out, "1", 64).exit_code, 0);
  const auto before = contents(out);
  ASSERT_TRUE(disk.make_read_only());
  const auto r = render("fog.json", out, "3", 64);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("Read-only file system"), std::string::npos) << r.err;
  EXPECT_EQ(contents(out), before);
  // However --out is written (a new folder, a trailing slash), the file system's refusal is 1.
  for (const std::string& other : {(disk.dir() / "new_folder").string(), (disk.dir() / "a" / "b").string(),
                                   out.string() + "/"}) {
    const auto refused = test::run_pyro(test::render_args("fog.json", other, "3", 64));
    EXPECT_EQ(refused.exit_code, 1) << other << ": " << refused.err;
    EXPECT_NE(refused.err.find("Read-only file system"), std::string::npos) << refused.err;
  }
  const auto trace = render("fog.json", dir / "frames", "1", 32, {"--trace", (out / "t.json").string()});
  EXPECT_NE(trace.exit_code, 0) << "a trace that cannot be written is no success";
  EXPECT_NE(trace.err.find("Read-only file system"), std::string::npos) << trace.err;
}

TEST(PyroCliFault, MountPointAsOutWorks) {
  const fs::path dir = test::scratch_dir("mount_point");
  test::ScratchMount disk(dir / "out", "size=4m");
  if (!disk.mounted()) GTEST_SKIP() << disk.why();
  const auto r = render("fog.json", disk.dir(), "3", 64);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"frame_0000.png", "frame_0001.png", "frame_0002.png"})
    EXPECT_TRUE(is_complete_png(read_bytes(disk.dir() / f))) << f;
  EXPECT_EQ(contents(disk.dir()).size(), 4u) << "three frames and the manifest, no staging left";
}

TEST(PyroCliFault, SecondWriterIsRefusedOrWaits) {
  const fs::path out = test::scratch_dir("lock") / "out";
  fs::create_directories(out);
  const int fd = ::open(out.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);  // not the child's
  ASSERT_EQ(::flock(fd, LOCK_EX), 0);  // stands for a run in progress
  const auto refused = render("fog.json", out, "1", 32);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--wait"), std::string::npos) << refused.err;
  EXPECT_TRUE(fs::is_empty(out));
  std::thread release([fd] {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ::close(fd);
  });
  const auto waited = render("fog.json", out, "1", 32, {"--wait"});
  release.join();
  EXPECT_EQ(waited.exit_code, 0) << waited.err;
  EXPECT_TRUE(fs::exists(out / "frame_0000.png"));
}

TEST(PyroCliFault, AnotherScenesFramesAreKeptUnlessOverwrite) {
  const fs::path out = test::scratch_dir("manifest") / "out";
  ASSERT_EQ(render("fog.json", out, "3", 32).exit_code, 0);
  const auto before = contents(out);
  const auto refused = render("explosion.json", out, "2", 32);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("fog.json"), std::string::npos) << "names what it holds: " << refused.err;
  EXPECT_NE(refused.err.find("--overwrite"), std::string::npos) << refused.err;
  EXPECT_EQ(contents(out), before);
  // The same scene file with other settings: its earlier render, alone in the folder, is replaced.
  const auto other_size = render("fog.json", out, "3", 48);
  EXPECT_EQ(other_size.exit_code, 0) << "same scene file, other settings: " << other_size.err;
  EXPECT_NE(other_size.err.find("width 32 -> 48"), std::string::npos) << other_size.err;
  const auto more = render("fog.json", out, "3:4", 48);
  EXPECT_EQ(more.exit_code, 0) << "same scene and settings add frames: " << more.err;
  EXPECT_EQ(contents(out).size(), 6u);

  const auto replaced = render("explosion.json", out, "2", 32, {"--overwrite"});
  ASSERT_EQ(replaced.exit_code, 0) << replaced.err;
  const auto after = contents(out);
  EXPECT_EQ(after.size(), 3u) << "only the explosion's two frames and the manifest";
  EXPECT_NE(after.at(".pyro_manifest.json").find("explosion.json"), std::string::npos);
}

TEST(PyroCliFault, StagingLeftByAKilledRunIsRemoved) {
  const fs::path dir = test::scratch_dir("stale");
  const fs::path out = dir / "out";
  const pid_t gone = fork();
  if (gone == 0) _exit(0);
  ASSERT_GT(gone, 0);
  waitpid(gone, nullptr, 0);  // its process id now names no process
  const std::string tag = ".partial-" + std::to_string(gone);
  fs::create_directories(out / tag);
  std::ofstream(out / tag / "frame_0000.png") << "cut";
  fs::create_directories(dir / (".out" + tag));  // the name beside --out older versions used
  const fs::path live = out / (".partial-" + std::to_string(getpid()));  // a live process's
  fs::create_directories(live);
  ASSERT_EQ(render("fog.json", out, "1", 32).exit_code, 0);
  EXPECT_FALSE(fs::exists(out / tag));
  EXPECT_FALSE(fs::exists(dir / (".out" + tag)));
  EXPECT_TRUE(fs::exists(live)) << "a staging folder whose process runs is left alone";
}

}  // namespace
}  // namespace pyro
