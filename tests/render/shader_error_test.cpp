// A shader that does not compile is reported with its file name and the driver's log.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "engine/gpu/gpu_error.h"
#include "engine/gpu/shader_program.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

TEST(ShaderErrors, CompileErrorNamesTheFileAndCarriesTheLog) {
  shared_headless_context().make_current();
  const auto dir = test::scratch_dir("content");
  std::filesystem::create_directories(dir / "shaders");
  std::ofstream(dir / "shaders" / "good.vert") << "#version 450 core\nvoid main() { gl_Position = vec4(0); }\n";
  std::ofstream(dir / "shaders" / "broken.frag")
      << "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(undeclared_thing); }\n";
  const std::string saved = content_dir();
  setenv("PYRO_CONTENT_DIR", dir.string().c_str(), 1);
  try {
    gpu::load_program("good.vert", "broken.frag");
    ADD_FAILURE() << "a broken shader must not link";
  } catch (const gpu::GpuError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("broken.frag"), std::string::npos) << what;
    EXPECT_NE(what.find("fragment shader does not compile"), std::string::npos) << what;
    EXPECT_NE(what.find("undeclared_thing"), std::string::npos) << "driver log expected: " << what;
  }
  setenv("PYRO_CONTENT_DIR", saved.c_str(), 1);
}

TEST(ShaderErrors, MissingShaderFileIsNamed) {
  shared_headless_context().make_current();
  EXPECT_THROW(
      {
        try {
          gpu::load_program("no_such.vert", "no_such.frag");
        } catch (const std::exception& e) {
          EXPECT_NE(std::string(e.what()).find("no_such.vert"), std::string::npos) << e.what();
          throw;
        }
      },
      std::exception);
}

}  // namespace
}  // namespace pyro
