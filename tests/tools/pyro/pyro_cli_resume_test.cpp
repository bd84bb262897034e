// Interrupted and concurrent runs end to end, with real pyro processes:
//  * a 60-frame render killed (SIGKILL) at random points, then `pyro render --resume`: the folder
//    holds the same bytes as an uninterrupted run's, 20 trials;
//  * two renders started into one folder: the second is refused while the first writes, or with
//    --wait runs after it, and the folder never mixes their frames.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/cli_render.h"
#include "tests/support/spawn_pyro.h"
#include "tests/support/test_paths.h"
#include "tests/support/under_asan.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Waits for `pid`; its exit code, or -signal when a signal ended it.
int finish_pyro_cli_resume(pid_t pid) {
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -1000;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// How many frames a `--resume` run said it kept ("resuming: K of N frame(s) already finished").
int frames_kept(const std::string& err) {
  const size_t at = err.find("resuming: ");
  return at == std::string::npos ? -1 : std::stoi(err.substr(at + 10));
}

bool holds_staging(const fs::path& out) {
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().filename().string().find(".partial-") != std::string::npos) return true;
  return false;
}

// The finished frames (renamed into place: no ".partial-" in the name) in `out` and its staging
// folders, as a killed run left them.
int finished_frames(const fs::path& out) {
  int n = 0;
  std::error_code ec;
  if (!fs::exists(out, ec)) return 0;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.rfind("frame_", 0) == 0 && name.find(".partial-") == std::string::npos)
      ++n;
  }
  return n;
}

// Whether a staging folder in `out` holds a finished frame.
bool staging_holds_a_frame(const fs::path& out) {
  for (const auto& e : fs::directory_iterator(out))
    if (e.is_directory() && e.path().filename().string().rfind(".partial-", 0) == 0)
      for (const auto& f : fs::directory_iterator(e.path()))
        if (f.path().extension() == ".png") return true;
  return false;
}

// Waits until `ready()` or `pid` is gone (false then).
template <class Ready>
bool wait_until(Ready ready, pid_t pid) {
  for (int i = 0; i < 6000; ++i) {
    if (ready()) return true;
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

// Waits until `out` holds a staging folder (the run holds the lock then) or `pid` is gone.
bool wait_for_staging(const fs::path& out, pid_t pid) {
  return wait_until([&] {
    std::error_code ec;
    return fs::exists(out, ec) && holds_staging(out);
  }, pid);
}

TEST(PyroCliResume, RendersKilledAtRandomPointsResumeToTheUninterruptedBytes) {
  const fs::path dir = test::scratch_dir("resume");
  const auto reference = test::render("fog.json", dir / "reference", "60", 48);
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  // The kills are spread over a warm run's time (the first may pay for cold caches).
  const auto t0 = Clock::now();
  ASSERT_EQ(test::render("fog.json", dir / "timed", "60", 48).exit_code, 0);
  const double run_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  const auto expected = test::contents(dir / "reference");
  ASSERT_EQ(expected.size(), 61u) << "60 frames and the manifest";

  // Instrumented builds run each trial several times slower: fewer trials there.
  const int trials = test::kUnderAsan ? 4 : 20;
  std::mt19937 random(20261201);
  std::uniform_real_distribution<double> when(0.05, 0.95);
  int killed_mid_run = 0, kept = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const fs::path out = dir / ("run" + std::to_string(trial));
    const pid_t run = test::spawn_pyro(test::render_args("fog.json", out, "60", 48));
    ASSERT_GT(run, 0);
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(when(random) * run_ms));
    ::kill(run, SIGKILL);
    if (finish_pyro_cli_resume(run) == -SIGKILL) ++killed_mid_run;
    const int finished = finished_frames(out);
    const auto resumed = test::render("fog.json", out, "60", 48, {"--resume"});
    ASSERT_EQ(resumed.exit_code, 0) << "trial " << trial << ": " << resumed.err;
    EXPECT_EQ(frames_kept(resumed.err), finished) << "trial " << trial << ": keeps every frame "
                                                     "the killed run finished: " << resumed.err;
    kept += std::max(0, frames_kept(resumed.err));
    EXPECT_EQ(test::contents(out), expected) << "trial " << trial << ": " << resumed.err;
  }
  std::printf("%d trials: %d killed before the render finished; --resume kept %d frame(s) in all\n",
              trials, killed_mid_run, kept);
  // The kills must land while frames are being made, and the resumed runs must keep some.
  EXPECT_GE(killed_mid_run, trials / 2);
  EXPECT_GT(kept, 0) << "no resumed run kept any frame a killed run had finished";
}

TEST(PyroCliResume, ResumeKeepsOnlyThisRendersFrames) {
  const fs::path dir = test::scratch_dir("resume_other");
  const fs::path out = dir / "out";
  ASSERT_EQ(test::render("fog.json", out, "0:2", 32).exit_code, 0);
  // Same folder, same scene and settings, a longer range: the three frames held are kept.
  const auto longer = test::render("fog.json", out, "0:4", 32, {"--resume"});
  ASSERT_EQ(longer.exit_code, 0) << longer.err;
  EXPECT_EQ(frames_kept(longer.err), 3) << longer.err;
  EXPECT_EQ(test::contents(out), test::contents([&] {
              EXPECT_EQ(test::render("fog.json", dir / "whole", "5", 32).exit_code, 0);
              return dir / "whole";
            }()));
  // Other settings: another run, whose frames are stale; with --resume every frame is drawn
  // again and the count said.
  const auto other = test::render("fog.json", out, "5", 40, {"--resume"});
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_EQ(frames_kept(other.err), 0) << other.err;
  EXPECT_NE(other.err.find("replacing 5 file(s)"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("width 32 -> 40"), std::string::npos) << other.err;
  EXPECT_EQ(test::contents(out), test::contents([&] {
              EXPECT_EQ(test::render("fog.json", dir / "whole40", "5", 40).exit_code, 0);
              return dir / "whole40";
            }()));
  // A killed run of other settings: its finished frames are not taken.
  const fs::path fresh = dir / "fresh";
  const pid_t other_run = test::spawn_pyro(test::render_args("fog.json", fresh, "200", 40));
  ASSERT_TRUE(wait_until([&] {
    std::error_code ec;
    return fs::exists(fresh, ec) && staging_holds_a_frame(fresh);
  }, other_run));
  ::kill(other_run, SIGKILL);
  finish_pyro_cli_resume(other_run);
  const auto resumed = test::render("fog.json", fresh, "5", 32, {"--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(frames_kept(resumed.err), 0) << resumed.err;
  EXPECT_EQ(test::contents(fresh), test::contents(dir / "whole"));
  const auto both = test::render("fog.json", out, "5", 32, {"--resume", "--overwrite"});
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("not both"), std::string::npos) << both.err;
}

TEST(PyroCliConcurrent, ASecondRenderIntoTheFolderIsRefusedOrWaitsAndNeverMixes) {
  const fs::path dir = test::scratch_dir("concurrent");
  const fs::path out = dir / "out";
  // 128 pixels a side: the fog render outlasts the explosion's start-up (its runtime is built
  // before it reaches the lock) with a margin.
  const pid_t fog = test::spawn_pyro(test::render_args("fog.json", out, "200", 128));
  ASSERT_GT(fog, 0);
  ASSERT_TRUE(wait_for_staging(out, fog)) << "the fog render never started writing";
  const auto refused = test::render("explosion.json", out, "120", 32);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--wait"), std::string::npos) << refused.err;
  // With --wait the explosion runs once the fog render is done, and is refused then: the
  // folder holds another scene's frames.
  const auto waited = test::render("explosion.json", out, "120", 32, {"--wait"});
  EXPECT_EQ(finish_pyro_cli_resume(fog), 0);
  EXPECT_EQ(waited.exit_code, 2) << waited.err;
  EXPECT_NE(waited.err.find("fog.json"), std::string::npos) << waited.err;
  const auto held = test::contents(out);
  EXPECT_EQ(held.size(), 201u) << "the 200 fog frames and the manifest, nothing else";
  EXPECT_NE(held.at(".pyro_manifest.json").find("fog.json"), std::string::npos);
  EXPECT_EQ(held.at(".pyro_manifest.json").find("explosion"), std::string::npos);
}

TEST(PyroCliConcurrent, TwoRangesOfOneRenderWithWaitBothLand) {
  const fs::path dir = test::scratch_dir("concurrent_ranges");
  const fs::path out = dir / "out";
  const pid_t first = test::spawn_pyro(test::render_args("fog.json", out, "0:39", 32, {"--wait"}));
  ASSERT_GT(first, 0);
  ASSERT_TRUE(wait_for_staging(out, first));
  const auto second = test::render("fog.json", out, "40:79", 32, {"--wait"});
  EXPECT_EQ(finish_pyro_cli_resume(first), 0);
  EXPECT_EQ(second.exit_code, 0) << second.err;
  ASSERT_EQ(test::render("fog.json", dir / "whole", "80", 32).exit_code, 0);
  EXPECT_EQ(test::contents(out), test::contents(dir / "whole"));
}

}  // namespace
}  // namespace pyro
