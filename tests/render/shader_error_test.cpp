// A shader that does not compile is reported with its file name and the driver's log.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "engine/gpu/gpu_error.h"
#include "engine/gpu/shader_program.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

// A scratch content directory with a shaders/ folder holding good.vert, made the content
// directory for the test's life.
class ScratchShaders {
 public:
  explicit ScratchShaders(const char* name)
      : dir_(test::scratch_dir(name)), saved_(content_dir()) {
    shared_headless_context().make_current();
    std::filesystem::create_directories(dir_ / "shaders");
    add("good.vert", "#version 450 core\nvoid main() { gl_Position = vec4(0); }\n");
    setenv("PYRO_CONTENT_DIR", dir_.string().c_str(), 1);
  }
  ~ScratchShaders() { setenv("PYRO_CONTENT_DIR", saved_.c_str(), 1); }
  void add(const char* file, const char* text) { std::ofstream(dir_ / "shaders" / file) << text; }

 private:
  std::filesystem::path dir_;
  std::string saved_;
};

TEST(ShaderErrors, CompileErrorNamesTheFileAndCarriesTheLog) {
  ScratchShaders shaders("content");
  shaders.add("broken.frag", "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(undeclared_thing); }\n");
  try {
    gpu::load_program("good.vert", "broken.frag");
    ADD_FAILURE() << "a broken shader must not link";
  } catch (const gpu::GpuError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("broken.frag"), std::string::npos) << what;
    EXPECT_NE(what.find("fragment shader does not compile"), std::string::npos) << what;
    EXPECT_NE(what.find("undeclared_thing"), std::string::npos) << "driver log expected: " << what;
  }
}

TEST(ShaderErrors, IncludesAreExpandedAndAMissingOneIsNamed) {
  ScratchShaders shaders("content_include");
  shaders.add("half.glsl", "float half_of(float v) { return 0.5 * v; }\n");
  shaders.add("uses.frag",
              "#version 450 core\n#include \"half.glsl\"\nout vec4 o;\nvoid main() { o = vec4(half_of(1.0)); }\n");
  shaders.add("missing.frag",
              "#version 450 core\nout vec4 o;\n#include \"nowhere.glsl\"\nvoid main() { o = vec4(1.0); }\n");
  shaders.add("late_error.frag",
              "#version 450 core\n#include \"half.glsl\"\nout vec4 o;\nvoid main() {\n  o = vec4(nope);\n}\n");
  EXPECT_NO_THROW(gpu::load_program("good.vert", "uses.frag"));
  try {
    gpu::load_program("good.vert", "missing.frag");
    ADD_FAILURE() << "a missing include must be an error";
  } catch (const gpu::GpuError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("missing.frag:3"), std::string::npos) << what;
    EXPECT_NE(what.find("nowhere.glsl"), std::string::npos) << what;
  }
  try {
    gpu::load_program("good.vert", "late_error.frag");
    ADD_FAILURE() << "an undeclared name must not compile";
  } catch (const gpu::GpuError& e) {
    // The error after the include is reported on the file's own line 5.
    const std::string what = e.what();
    EXPECT_NE(what.find(":5"), std::string::npos) << what;
  }
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
