// The child-process boundary around third-party readers (engine/io/isolated_call.h): a result
// comes back byte for byte; a UserError comes back with its file and place; a crash, an
// allocation over the cap and a hang each become a UserError naming the file, and the calling
// process goes on.
#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/isolated_call.h"

namespace pyro {
namespace {

IsolationLimits quick(double seconds = 20.0, uint64_t memory = uint64_t{256} << 20) {
  IsolationLimits l;
  l.timeout_seconds = seconds;
  l.memory_bytes = memory;
  return l;
}

std::string refusal(const std::function<void(ResultWriter&)>& work, const IsolationLimits& limits) {
  try {
    run_isolated("damaged.vdb", "reading it", work, [](std::string_view) {}, limits);
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), "damaged.vdb");
    return e.what();
  }
  return "";
}

TEST(IsolatedCall, ALargeResultComesBackByteForByte) {
  const size_t n = 3'000'017;  // not a multiple of the page size, larger than one growth step
  std::vector<char> got;
  run_isolated(
      "f", "making bytes",
      [&](ResultWriter& out) {
        out.append("ab", 2);
        char* p = out.extend(n);
        for (size_t i = 0; i < n; ++i) p[i] = static_cast<char>(i * 31 % 251);
      },
      [&](std::string_view bytes) { got.assign(bytes.begin(), bytes.end()); }, quick());
  ASSERT_EQ(got.size(), n + 2);
  EXPECT_EQ(got[0], 'a');
  for (size_t i = 0; i < n; i += 9973) ASSERT_EQ(got[i + 2], static_cast<char>(i * 31 % 251));
}

TEST(IsolatedCall, AUserErrorKeepsItsFileAndPlace) {
  try {
    run_isolated(
        "f.vdb", "reading",
        [](ResultWriter& out) {
          out.append("partial", 7);
          throw UserError("f.vdb", "grid \"density\"", "a float grid");
        },
        [](std::string_view) { FAIL() << "no result expected"; }, quick());
    FAIL() << "no error came back";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), "f.vdb");
    EXPECT_EQ(e.place(), "grid \"density\"");
    EXPECT_EQ(e.expected(), "a float grid");
  }
}

TEST(IsolatedCall, ACrashInTheChildIsAUserError) {
  const std::string why = refusal([](ResultWriter&) { std::raise(SIGSEGV); }, quick());
  EXPECT_NE(why.find("signal"), std::string::npos) << why;
  // The parent is unharmed and can go on.
  std::string again;
  run_isolated(
      "f", "again", [](ResultWriter& out) { out.append("ok", 2); },
      [&](std::string_view b) { again = std::string(b); }, quick());
  EXPECT_EQ(again, "ok");
}

TEST(IsolatedCall, AnAllocationOverTheCapIsAUserError) {
  // 1 GiB asked of a child allowed 64 MiB more: refused, where without the cap it would succeed.
  const std::string why = refusal(
      [](ResultWriter&) {
        std::vector<char> big(size_t{1} << 30, 1);
        if (big[12345] != 1) std::abort();
      },
      quick(20.0, uint64_t{64} << 20));
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("memory"), std::string::npos) << why;
}

TEST(IsolatedCall, AHangIsStoppedAtTheDeadline) {
  const auto start = std::chrono::steady_clock::now();
  const std::string why = refusal(
      [](ResultWriter&) {
        for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(50));
      },
      quick(0.5));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(why.find("did not finish"), std::string::npos) << why;
  EXPECT_LT(seconds, 10.0);
}

}  // namespace
}  // namespace pyro
