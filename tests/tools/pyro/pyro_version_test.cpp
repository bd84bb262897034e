// pyro --version: the project's version (CMakeLists.txt's project VERSION) and the headless
// OpenGL context's version and renderer; without any context the version still prints, exit 0.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/test_paths.h"

namespace pyro {
namespace {

// The VERSION of project(pyrocumulus VERSION x.y.z ...) in the top-level CMakeLists.txt, read
// independently of the build. (Plain string search: std::regex trips g++ 12's
// -Wmaybe-uninitialized under -O2 -Werror.)
std::string project_version() {
  std::ifstream in(std::string(PYRO_SOURCE_DIR) + "/CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::size_t project = s.find("project(");
  if (project == std::string::npos) return "";
  const std::size_t keyword = s.find("VERSION", project);
  if (keyword == std::string::npos || keyword > s.find(')', project)) return "";
  std::size_t begin = s.find_first_not_of(" \t\n", keyword + 7);
  std::size_t end = s.find_first_not_of("0123456789.", begin);
  if (begin == std::string::npos || end == begin) return "";
  return s.substr(begin, end - begin);
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
