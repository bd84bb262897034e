// Every input that once crashed a fuzz target (tests/fuzz/regressions/<target>/) and every seed
// of the corpus (tests/fuzz/corpus/<target>/) is fed to its target in the normal suite: each must
// be handled (accepted, or refused with a UserError or CLI11's parse error), never escape as
// another exception. The sanitizer preset (asan-ubsan) turns memory errors here into failures.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>

#include "tests/fuzz/fuzz_targets.h"

#include "tests/support/under_asan.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

using test::kUnderAsan;

// Feeds every input under tests/fuzz/<folder>/<target>/ to its target and returns how many each
// target was fed. A missing folder is a failure, not an empty result.
std::map<std::string, std::size_t> feed_all(const std::string& folder) {
  const fs::path root = fs::path(PYRO_SOURCE_DIR) / "tests" / "fuzz" / folder;
  std::map<std::string, std::size_t> fed;
  if (!fs::is_directory(root)) {
    ADD_FAILURE() << root << " is missing: the inputs are committed with the tests";
    return fed;
  }
  for (const auto& target : fs::directory_iterator(root)) {
    if (!target.is_directory()) continue;
    const std::string name = target.path().filename().string();
    std::size_t& inputs = fed[name];
    for (const auto& entry : fs::directory_iterator(target.path())) {
      if (!entry.is_regular_file()) continue;
      // Inputs named *.no_asan.* make a library ask for an absurd buffer (2^56 bytes): a release
      // build gets std::bad_alloc and refuses the file (exit 2), but AddressSanitizer stops the
      // process on such a request instead of throwing, so they are fed only without it.
      if (kUnderAsan && entry.path().filename().string().find(".no_asan.") != std::string::npos)
        continue;
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string input{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      bool known = false;
      EXPECT_NO_THROW(known = fuzz::run(name, input)) << entry.path();
      EXPECT_TRUE(known) << "no fuzz target named " << name << " (" << target.path() << ")";
      ++inputs;
    }
  }
  return fed;
}

// Every target in `expected` was fed at least one input from `folder`.
void expect_inputs_for(const std::string& folder, const std::set<std::string>& expected) {
  const std::map<std::string, std::size_t> fed = feed_all(folder);
  for (const std::string& target : expected) {
    const auto it = fed.find(target);
    EXPECT_TRUE(it != fed.end() && it->second > 0)
        << "no input fed from tests/fuzz/" << folder << "/" << target << "/";
  }
}

TEST(FuzzInputs, SeedCorpusIsHandled) { expect_inputs_for("corpus", {"cli", "particles", "png", "scene", "vdb"}); }

// The targets that have had a crash, each kept as an input (tools/fuzz.sh says where they go).
TEST(FuzzInputs, RegressionsAreHandled) { expect_inputs_for("regressions", {"png", "vdb"}); }

TEST(FuzzInputs, CommandLineCallbacksAreRemoved) {
  // A render command line that would write frames: parsed only, nothing written.
  const fs::path out = fs::temp_directory_path() / "pyro_fuzz_cli_should_not_exist";
  fs::remove_all(out);
  const std::string line = "render\n" + std::string(PYRO_SOURCE_DIR) +
                           "/content/scenes/mist.json\n--out\n" + out.string() + "\n--frames\n2";
  EXPECT_TRUE(fuzz::run("cli", line));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace pyro
