// Bounded cost for any input: a scene whose one unknown key is 50 MB long is refused by a child
// `pyro render` held to a 300 MB address space and 20 s of CPU, with exit 2 and a message under
// 1 KB. The child's CPU seconds and peak resident memory (getrusage) are printed and recorded as
// properties; its peak resident memory stays under 100 MB (the file is 50 MB).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/test_paths.h"

#include "tests/support/file_bytes.h"
#include "tests/support/spawn_pyro.h"
#include "tests/support/under_asan.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

using test::kUnderAsan;

struct LimitedRun {
  int exit_code = -1;
  double cpu_seconds = 0;
  long peak_rss_kib = 0;
  std::string err;
};

// The address space pyro gets: its shared libraries alone map about 280 MB of it (FFmpeg's
// libavformat brings TLS, codec and ICU libraries), so 600 MB leaves the 50 MB scene room for
// its text once and a little more, not for copies of it. The resident-memory comparison below
// is the finer bound.
constexpr rlim_t kAddressSpace = 600u << 20;

// Runs pyro `args` in a child with RLIMIT_AS = `address_space` bytes and RLIMIT_CPU = `cpu_s`.
LimitedRun run_limited(const std::vector<std::string>& args, rlim_t address_space, rlim_t cpu_s,
                       const fs::path& err_file) {
  const int err = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const pid_t pid = test::spawn_pyro(args, err, [&] {
    const rlimit as{address_space, address_space}, cpu{cpu_s, cpu_s};
    if (!kUnderAsan) setrlimit(RLIMIT_AS, &as);
    setrlimit(RLIMIT_CPU, &cpu);
  });
  close(err);
  LimitedRun r;
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.cpu_seconds = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
                  1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  r.peak_rss_kib = usage.ru_maxrss;
  r.err = test::read_bytes(err_file);
  return r;
}

// A scene whose cloud has one unknown key of `key_bytes` bytes ('r' repeated).
fs::path long_key_scene(const fs::path& dir, size_t key_bytes) {
  const fs::path scene = dir / "long_key.json";
  std::ofstream f(scene, std::ios::binary);
  f << "{\"clouds\": [{\"count\": 10, \"";
  const std::string chunk(std::min<size_t>(key_bytes, 1 << 20), 'r');
  for (size_t i = 0; i < key_bytes / chunk.size(); ++i) f << chunk;
  f << "\": 1}]}";
  return scene;
}

TEST(PyroCliBoundedCost, FiftyMegabyteUnknownKeyIsRefusedCheaplyWithAShortMessage) {
  const fs::path dir = test::scratch_dir("long_key");
  const size_t key_bytes = 50u << 20;
  const fs::path scene = long_key_scene(dir, key_bytes);
  const LimitedRun r = run_limited({"render", scene.string(), "--out", (dir / "out").string()},
                                   kAddressSpace, 20, dir / "err.txt");
  RecordProperty("cpu_seconds", std::to_string(r.cpu_seconds));
  RecordProperty("peak_rss_kib", std::to_string(r.peak_rss_kib));
  std::printf("50 MB unknown key: exit %d, %.2f s CPU, peak RSS %ld KiB, message %zu bytes\n",
              r.exit_code, r.cpu_seconds, r.peak_rss_kib, r.err.size());
  EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 2000);
  EXPECT_LT(r.err.size(), 1024u) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find(scene.string() + ": at line 1, column 27: strings of at most"),
            std::string::npos) << "names the file and where the string starts: " << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find(std::to_string(key_bytes) + " bytes"), std::string::npos)
      << "says how long the string is: " << r.err.substr(0, 2000);
  if (!kUnderAsan) {
    // Against pyro refusing a scene of a few bytes in the same way (the program's own libraries):
    // the file's text is held once (50 MB), not copied (a copy alone would add another 50 MB).
    const fs::path tiny = dir / "tiny_unknown_key.json";
    std::ofstream(tiny, std::ios::binary) << "{\"clouds\": [{\"count\": 10, \"r\": 1}]}";
    const LimitedRun base = run_limited({"render", tiny.string(), "--out", (dir / "out").string()}, kAddressSpace, 20,
                                        dir / "err_tiny.txt");
    ASSERT_EQ(base.exit_code, 2) << base.err;
    std::printf("the same refusal of a %zu-byte scene: peak RSS %ld KiB\n", size_t(fs::file_size(tiny)),
                base.peak_rss_kib);
    EXPECT_LT(r.peak_rss_kib - base.peak_rss_kib, long(key_bytes / 1024) * 3 / 2)
        << "the file costs about its own size, not copies of it";
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// Below the loader's string limit the key reaches the did-you-mean suggestion and the message:
// both stay bounded (no suggestion for a key that long, the key quoted cut).
TEST(PyroCliBoundedCost, LongUnknownKeyIsQuotedCut) {
  const fs::path dir = test::scratch_dir("quoted_cut");
  const fs::path scene = long_key_scene(dir, 60000);
  const LimitedRun r = run_limited({"render", scene.string(), "--out", (dir / "out").string()},
                                   1u << 30, 20, dir / "err.txt");
  EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 2000);
  EXPECT_LT(r.err.size(), 1024u) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("unknown key \"" + std::string(60, 'r') + "\u2026 (60000 bytes)\""),
            std::string::npos) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("expected one of \"name\""), std::string::npos) << r.err.substr(0, 2000);
}

}  // namespace
}  // namespace pyro
