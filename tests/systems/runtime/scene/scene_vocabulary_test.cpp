// One vocabulary: every enum-valued key of a scene file accepts exactly its enum's table names
// (engine/core/enum_names.h), and a bad name is refused with the JSON pointer and every accepted
// name from the same table. The command line's options use the same tables.
#include <gtest/gtest.h>

#include <string>

#include "components/emitter.h"
#include "components/flipbook_fire.h"
#include "components/mesh_instance.h"
#include "components/particle_medium.h"
#include "components/render_modes.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

std::string error_of_scene_vocabulary(const std::string& text) {
  try {
    parse_scene(text, "vocabulary.json");
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

// `scene` with NAME where the enum's name goes.
template <class E>
void expect_vocabulary(const std::string& scene, const std::string& pointer) {
  for (std::string_view name : enum_name_views<E>()) {
    std::string text = scene;
    text.replace(text.find("NAME"), 4, std::string(name));
    const std::string message = error_of_scene_vocabulary(text);
    // A good name may still fail a rule between keys (explosion shading needs non-Gaussian
    // particles); never because of the name itself.
    EXPECT_EQ(message.find("unknown"), std::string::npos) << name << ": " << message;
  }
  std::string bad = scene;
  bad.replace(bad.find("NAME"), 4, "bogus");
  const std::string message = error_of_scene_vocabulary(bad);
  EXPECT_NE(message.find(pointer), std::string::npos) << message;
  EXPECT_NE(message.find(enum_name_list<E>()), std::string::npos) << message;
}

TEST(SceneVocabulary, EveryEnumKeyTakesItsTablesNames) {
  expect_vocabulary<BillboardAlignment>(R"({"render": {"billboards": "NAME"}})", "/render/billboards");
  expect_vocabulary<ParticleShape>(R"({"render": {"particles": "NAME"}})", "/render/particles");
  expect_vocabulary<ParticleShading>(
      R"({"render": {"particles": "spherical", "shading": "NAME"}})", "/render/shading");
  expect_vocabulary<EyeOrder>(R"({"camera": {"stereo": {"eye_order": "NAME"}}})",
                              "/camera/stereo/eye_order");
  expect_vocabulary<MeshKind>(R"({"meshes": [{"type": "NAME"}]})", "/meshes/0/type");
  expect_vocabulary<ParticleMedium>(R"({"emitters": [{"medium": "NAME"}]})", "/emitters/0/medium");
  expect_vocabulary<EmitterShape>(R"({"emitters": [{"shape": {"type": "NAME"}}]})",
                                  "/emitters/0/shape/type");
  expect_vocabulary<FlipbookBlend>(R"({"fires": [{"blend": "NAME"}]})", "/fires/0/blend");
}

TEST(CliVocabulary, EveryEnumOptionTakesItsTablesNames) {
  const std::string scene = test::scene_path("fog.json");
  const auto refused = [&](const std::string& option) {
    return test::run_pyro({"render", scene, "--out", "/nonexistent/never", option, "bogus"});
  };
  const auto expect_listed = [&](const std::string& option, const std::string& names) {
    const test::CommandResult r = refused(option);
    EXPECT_EQ(r.exit_code, 2) << option;
    EXPECT_NE(r.err.find(names), std::string::npos) << option << ": " << r.err;
  };
  // CLI11 lists the members it accepts; the help text lists the table's names.
  expect_listed("--stereo", "side-by-side-crossed");
  expect_listed("--billboards", "viewpoint");
  expect_listed("--particles", "spherical");
  expect_listed("--eye-order", "right-left");
  const test::CommandResult help = test::run_pyro({"render", "--help"});
  EXPECT_NE(help.out.find(enum_name_list<StereoMode>()), std::string::npos) << help.out;
  EXPECT_NE(help.out.find(enum_name_list<ParticleShape>()), std::string::npos) << help.out;
}

}  // namespace
}  // namespace pyro
