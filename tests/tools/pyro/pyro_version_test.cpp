// pyro --version: the project's version (CMakeLists.txt's project VERSION) and the headless
// OpenGL context's version and renderer; without any context the version still prints, exit 0.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "tests/support/test_paths.h"

namespace pyro {
namespace {

// The VERSION of project(...) in the top-level CMakeLists.txt, read independently of the build.
std::string project_version() {
  std::ifstream in(std::string(PYRO_SOURCE_DIR) + "/CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string s = text.str();
  if (!std::regex_search(s, m, std::regex(R"(project\(\s*pyrocumulus\s+VERSION\s+([0-9.]+))")))
    return "";
  return m[1];
}

TEST(PyroVersion, PrintsTheProjectVersionAndTheRenderer) {
  const std::string version = project_version();
  ASSERT_FALSE(version.empty());
  const test::CommandResult r = test::run_pyro({"--version"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("pyro " + version + "\n", 0), 0u) << r.out;
  // "renderer: OpenGL 4.5 (Core Profile) Mesa ... / llvmpipe (...)": GL_VERSION / GL_RENDERER.
  EXPECT_NE(r.out.find("\nrenderer: OpenGL 4."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" / "), std::string::npos) << r.out;
}

TEST(PyroVersion, WithoutAContextSaysSoAndStillPrintsTheVersion) {
  // No EGL vendor library: libglvnd finds no driver, so no context can be made.
  const test::CommandResult r = test::run_pyro_with(
      "env __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json", {"--version"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("pyro " + project_version() + "\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("renderer: none (no headless OpenGL context could be made"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace pyro
