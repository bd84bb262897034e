#include "tools/bake/six_way_bake.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "components/ambient_light.h"
#include "components/directional_light.h"
#include "components/frame_image.h"
#include "components/view.h"
#include "engine/core/user_error.h"
#include "engine/io/folder_replacement.h"
#include "engine/io/png_file.h"
#include "engine/io/text_file.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

constexpr const char* kFolderA = "six_way_a";
constexpr const char* kFolderB = "six_way_b";
constexpr const char* kSidecar = "six_way.json";

// Every light of the world set for the pass (the first directional light is the sun and the
// ambient lights add up: systems/lighting); returns the lights as they were.
struct WorldLights {
  std::vector<DirectionalLight> directional;
  std::vector<AmbientLight> ambient;
};

WorldLights swap_lights(ecs::World& world, const WorldLights& next) {
  WorldLights before;
  size_t i = 0;
  world.each<DirectionalLight>([&](DirectionalLight& l) {
    before.directional.push_back(l);
    l = next.directional[std::min(i++, next.directional.size() - 1)];
  });
  i = 0;
  world.each<AmbientLight>([&](AmbientLight& l) {
    before.ambient.push_back(l);
    l = next.ambient[std::min(i++, next.ambient.size() - 1)];
  });
  return before;
}

WorldLights pass_lights(const SixWayPassLight& pass) {
  WorldLights lights;
  DirectionalLight sun;
  sun.direction = pass.travel;
  sun.color = pass.sun;
  sun.intensity = 1.0f;
  AmbientLight ambient;
  ambient.color = pass.ambient;
  AmbientLight none;
  none.color = glm::vec3(0.0f);
  lights.directional = {sun};
  lights.ambient = {ambient, none};  // the first carries the ambient, any others add nothing
  return lights;
}

std::string frame_name(int f) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", f);
  return name;
}

}  // namespace

void check_six_way_bake(const SceneDescription& scene, const SixWayBakeOptions& options,
                        const std::string& out) {
  const std::string file = scene.file.empty() ? "scene" : scene.file;
  if (!scene.fires.empty())
    throw UserError(file, "/fires",
                    "expected a scene of simulated smoke to bake, found flipbook fires");
  if (!scene.shadows)
    throw UserError(file, "/shadows",
                    "expected lit media for six-way lightmaps (a \"shadows\" block), found none");
  if (scene.directional_lights.empty() || scene.ambient_lights.empty())
    throw UserError(file, "/lights",
                    "expected a directional and an ambient light for the six-way passes to set");
  std::error_code ec;
  if (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec))
    throw UserError(out, "--out", "expected a folder for the six-way lightmaps, found a file");
  if (options.loop_blend < 0 || options.loop_blend >= options.frames)
    throw UserError("", "--loop-blend",
                    "expected a cross-fade shorter than the flipbook (0 to " +
                        std::to_string(options.frames - 1) + " frames), found " +
                        std::to_string(options.loop_blend));
}

RuntimeOptions six_way_runtime_options(const SixWayBakeOptions& options) {
  RuntimeOptions runtime_options;
  runtime_options.readback = true;
  runtime_options.width_override = options.width;
  runtime_options.height_override = options.height;
  return runtime_options;
}

RgbImage render_six_way_pass(SceneRuntime& runtime, const SixWayPassLight& pass) {
  const WorldLights before = swap_lights(runtime.world(), pass_lights(pass));
  runtime.redraw();
  RgbImage image = rgb_of(runtime.image());
  swap_lights(runtime.world(), before);
  return image;
}

SixWayFrame render_six_way_frame(SceneRuntime& runtime) {
  const CameraFrame camera = runtime.world().resource<View>().eyes.at(0);
  const SixWayRenders renders = render_six_way_passes(
      camera, [&](const SixWayPassLight& pass) { return render_six_way_pass(runtime, pass); });
  return six_way_frame_from_renders(renders.faces, renders.opacity);
}

nlohmann::json six_way_sidecar(const SceneDescription& scene, const SixWayBakeOptions& options) {
  return {{"format", "six-way lightmaps (Unity VFX Graph packing)"},
          {"frames", options.frames},
          {"width", options.width},
          {"height", options.height},
          {"frames_per_second", scene.frames_per_second},
          {"loop_blend", options.loop_blend},
          {"source", scene.file},
          {"frame", "x right, y up, z towards the viewer (the baking camera's)"},
          {"textures",
           {{"a",
             {{"folder", kFolderA},
              {"r", "right: light at +x"},
              {"g", "top: light at +y"},
              {"b", "back: light behind the smoke, at -z"},
              {"a", "alpha"}}},
            {"b",
             {{"folder", kFolderB},
              {"r", "left: light at -x"},
              {"g", "bottom: light at -y"},
              {"b", "front: light at the viewer's side, +z"},
              {"a", "emissive (0: smoke)"}}}}},
          {"color_space", "linear"},
          {"premultiplied", false},
          {"blend",
           "lighting = sum over axes of w_axis^2 * (w_axis >= 0 ? positive face : negative "
           "face), w the unit vector towards the light; colour = light * lighting * alpha"}};
}

SixWayBakeResult bake_six_way(SceneRuntime& runtime, const SixWayBakeOptions& options,
                              const std::string& out) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  FolderReplacement staging(out, flipbook_bake_output_kind(), options.overwrite);
  fs::create_directories(staging.path() / kFolderA);
  fs::create_directories(staging.path() / kFolderB);
  SixWayBakeResult result;
  result.removed_leftovers = staging.removed_leftovers();
  result.restored_old_folder = staging.restored_old_folder();
  std::vector<std::string> files_a(options.frames), files_b(options.frames);
  const auto write = [&](int f, const SixWayFrame& frame) {
    const SixWayTextures t = pack_six_way(frame);
    write_png((staging.path() / kFolderA / frame_name(f)).string(), t.width, t.height, 4, t.a);
    write_png((staging.path() / kFolderB / frame_name(f)).string(), t.width, t.height, 4, t.b);
    files_a[f] = (fs::path(out) / kFolderA / frame_name(f)).string();
    files_b[f] = (fs::path(out) / kFolderB / frame_name(f)).string();
  };
  // Frames below loop_blend wait for the simulated frame `frames` steps later to cross-fade with
  // (weight (j + 1) / (loop_blend + 1) on frame j, as the flame bake).
  std::vector<SixWayFrame> waiting;
  for (int f = 0; f < options.frames + options.loop_blend; ++f) {
    runtime.step();
    SixWayFrame frame = render_six_way_frame(runtime);
    if (f < options.loop_blend) {
      waiting.push_back(std::move(frame));
    } else if (f < options.frames) {
      write(f, frame);
    } else {
      const int j = f - options.frames;
      const float w = static_cast<float>(j + 1) / static_cast<float>(options.loop_blend + 1);
      write(j, cross_fade_six_way(waiting[static_cast<size_t>(j)], frame, w));
    }
  }
  write_text_file((staging.path() / kSidecar).string(),
                  six_way_sidecar(runtime.scene(), options).dump(2) + "\n");
  result.files = files_a;
  result.files.insert(result.files.end(), files_b.begin(), files_b.end());
  result.files.push_back((fs::path(out) / kSidecar).string());
  staging.commit();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace pyro
