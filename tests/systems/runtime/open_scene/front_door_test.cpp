// No command, viewer, benchmark or chart builds a SceneRuntime of its own: they open scenes through
// the front door (systems/runtime/open_scene/open_scene.h), so that a scene's quality pick applies to every
// one of them. A construction kept on purpose (a benchmark measuring the settings it sets itself)
// says why with "behind the front door" on its line or the line above. The machinery behind the
// door (systems/runtime/scene_runtime, systems/runtime/quality_picker) and the tests are not scanned.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace pyro {
namespace {

namespace fs = std::filesystem;

constexpr const char* kReason = "behind the front door";

// Where code opens scenes for a user: every source file under these folders of the tree.
const std::vector<std::string> kScannedFolders = {"tools/pyro", "tools/viewer",
                                                  "tools/bench", "tools/charts"};

std::string without_comment(const std::string& line) {
  const size_t at = line.find("//");
  return at == std::string::npos ? line : line.substr(0, at);
}

// A SceneRuntime made here: a variable constructed inside a function (an indented
// `SceneRuntime name(`, `SceneRuntime name{`), a temporary (`SceneRuntime(`, not a qualified
// `SceneRuntime::SceneRuntime(`) or `make_unique<SceneRuntime>`. A function returning one by value
// is declared unindented and is not a construction.
bool constructs_runtime(const std::string& line) {
  static const std::regex variable(R"(^\s+(const\s+)?(pyro::)?SceneRuntime\s+[A-Za-z_]\w*\s*[({])");
  static const std::regex temporary(R"((^|[^:\w~])SceneRuntime\s*[({])");
  static const std::regex made(R"(make_(unique|shared)\s*<\s*(pyro::)?SceneRuntime\s*>)");
  const std::string code = without_comment(line);
  return std::regex_search(code, variable) || std::regex_search(code, temporary) ||
         std::regex_search(code, made);
}

// "file:line: text" for each construction in `text` without a reason beside it.
std::vector<std::string> unexplained_constructions(const std::string& file,
                                                   const std::string& text) {
  std::vector<std::string> found;
  std::istringstream in(text);
  std::string line, previous;
  for (int number = 1; std::getline(in, line); ++number, previous = line) {
    const bool explained =
        line.find(kReason) != std::string::npos || previous.find(kReason) != std::string::npos;
    if (constructs_runtime(line) && !explained)
      found.push_back(file + ":" + std::to_string(number) + ": " + line);
  }
  return found;
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(FrontDoor, TheScanFindsEachWayOfMakingARuntime) {
  const std::string text =
      "SceneRuntime relit_runtime(VolumeAsset volume) {\n"         // 1: a function: not one
      "  SceneRuntime runtime(scene, options);\n"                  // 2
      "  return std::make_unique<SceneRuntime>(scene, o);\n"       // 3
      "  return SceneRuntime(resolved, std::move(assets), ro);\n"  // 4
      "  SceneRuntime measured(scene, a), reference(scene, b);\n"  // 5
      "  SceneRuntime& runtime = *opened.runtime;\n"               // 6: a reference: not one
      "SceneRuntime::SceneRuntime(const SceneDescription& s)\n"    // 7: the definition: not one
      "  // behind the front door: measures the layer scales it sets\n"
      "  SceneRuntime timed(scene, o);\n"                                            // 9: explained
      "  SceneRuntime probe(s, ro);  // behind the front door: a synthetic scene\n"  // 10
      "  // SceneRuntime runtime(scene);\n";  // 11: a comment
  const std::vector<std::string> found = unexplained_constructions("f.cpp", text);
  ASSERT_EQ(found.size(), 4u) << ::testing::PrintToString(found);
  EXPECT_EQ(found[0].rfind("f.cpp:2:", 0), 0u) << found[0];
  EXPECT_EQ(found[1].rfind("f.cpp:3:", 0), 0u) << found[1];
  EXPECT_EQ(found[2].rfind("f.cpp:4:", 0), 0u) << found[2];
  EXPECT_EQ(found[3].rfind("f.cpp:5:", 0), 0u) << found[3];
}

TEST(FrontDoor, NoCommandOutsideTheFrontDoorConstructsTheRuntime) {
  const fs::path root = PYRO_SOURCE_DIR;
  std::vector<std::string> found;
  int files = 0;
  for (const std::string& folder : kScannedFolders) {
    ASSERT_TRUE(fs::is_directory(root / folder)) << (root / folder);
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root / folder)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      ++files;
      const std::string name = fs::relative(e.path(), root).string();
      for (const std::string& f : unexplained_constructions(name, read_text(e.path())))
        found.push_back(f);
    }
  }
  EXPECT_GT(files, 40);
  std::string listing;
  for (const std::string& f : found) listing += "\n  " + f;
  EXPECT_TRUE(found.empty())
      << "constructs a SceneRuntime instead of opening the scene with open_scene "
         "(systems/runtime/open_scene/open_scene.h), or says why beside it with \""
      << kReason << "\":" << listing;
}

}  // namespace
}  // namespace pyro
