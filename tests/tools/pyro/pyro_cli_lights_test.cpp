// The scene's lights as a list: `"light": {...}` and the `"lights"` list that says the same render
// the same bytes (the lights are entities either way, gathered by the light phase), and a scene
// without lights differs (the sun and the sky did reach the pixels).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/cli_render.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

fs::path write_scene_pyro_cli_lights(const fs::path& dir, const std::string& name, const nlohmann::json& scene) {
  const fs::path p = dir / name;
  std::ofstream(p) << scene.dump(2);
  return p;
}

std::string render_frame(const fs::path& scene, const fs::path& out) {
  const auto r = test::run_pyro({"render", scene.string(), "--out", out.string(), "--frames", "0:1",
                                 "--width", "48", "--height", "48"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return test::read_bytes(out / "frame_0001.png");
}

TEST(PyroCliLights, TheLightListSayingTheSameRendersTheSameBytes) {
  const fs::path dir = test::scratch_dir("lights_list");
  nlohmann::json scene = nlohmann::json::parse(test::read_bytes(test::scene_path("explosion.json")));
  scene["light"] = {{"direction", {-0.3, -1.0, 0.2}}, {"color", {1.0, 0.9, 0.7}}, {"ambient", {0.2, 0.25, 0.3}}};
  const std::string short_form = render_frame(write_scene_pyro_cli_lights(dir, "short.json", scene), dir / "short");

  scene.erase("light");
  scene["lights"] = {{{"type", "ambient"}, {"color", {0.2, 0.25, 0.3}}},
                     {{"type", "directional"}, {"direction", {-0.3, -1.0, 0.2}}, {"color", {1.0, 0.9, 0.7}}}};
  EXPECT_EQ(render_frame(write_scene_pyro_cli_lights(dir, "list.json", scene), dir / "list"), short_form);

  scene["lights"] = nlohmann::json::array();
  EXPECT_NE(render_frame(write_scene_pyro_cli_lights(dir, "dark.json", scene), dir / "dark"), short_form);
}

}  // namespace
}  // namespace pyro
