// Culling before the sort changes no image: every shipped scene, from its own camera and from a
// camera among its particles, mono and side by side, renders the same bytes with the sorting
// system's culling on and off (RenderSettings::cull_particles), and from among the particles
// the lists are shorter with it on.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "components/frame_image.h"
#include "components/render_settings.h"
#include "engine/core/content_path.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

struct Frames {
  std::vector<std::vector<float>> images;
  size_t drawn = 0;  // the first view's list, summed over the frames
};

Frames render_culling_frames(const SceneDescription& scene, StereoMode mode, bool cull) {
  RuntimeOptions o;
  o.width_override = 80;
  o.height_override = 60;
  o.stereo_mode = mode;
  // The CPU orders every frame: a GPU-ordered frame keeps no list on the CPU to count, and the
  // automatic choice between them is timed. The GPU's order is checked by GpuSortFrames.
  o.sort_device = SortDevice::cpu;
  SceneRuntime run(scene, o);
  run.world().resource<RenderSettings>().cull_particles = cull;
  Frames f;
  for (int frame = 0; frame < 3; ++frame) {
    run.step();
    f.images.push_back(run.image().rgba);
    f.drawn += run.world().resource<EyeDrawLists>().eyes.at(0).size();
  }
  return f;
}

// A point among the scene's particles: its first cloud box's or emitter's centre, else none.
std::optional<glm::vec3> among_particles(const SceneDescription& s) {
  if (!s.clouds.empty()) return 0.5f * (s.clouds[0].box_min + s.clouds[0].box_max);
  if (!s.emitters.empty()) return s.emitters[0].emitter.position + glm::vec3(0, 0.5f, 0);
  return std::nullopt;
}

TEST(CullingFrames, EveryShippedSceneRendersTheSameBytesWithAndWithoutCulling) {
  size_t scenes = 0, inside_views = 0, inside_views_culled = 0;
  for (const auto& entry : std::filesystem::directory_iterator(content_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().filename().string();
    SceneDescription scene = load_scene(entry.path().string());
    scene.quality = {};  // the settings as written: a quality search times candidates
    ++scenes;
    std::vector<SceneDescription> views = {scene};
    if (const auto inside = among_particles(scene)) {
      SceneDescription from_inside = scene;
      from_inside.camera.position = *inside;
      from_inside.camera.target = *inside + glm::vec3(4.0f, 0.0f, 1.0f);
      from_inside.camera.orbit_deg_per_second = 0.0f;
      views.push_back(from_inside);
    }
    for (size_t v = 0; v < views.size(); ++v)
      for (const StereoMode mode : {StereoMode::mono, StereoMode::side_by_side}) {
        const Frames on = render_culling_frames(views[v], mode, true), off = render_culling_frames(views[v], mode, false);
        for (size_t f = 0; f < on.images.size(); ++f)
          EXPECT_TRUE(on.images[f] == off.images[f])
              << name << (v ? " from among its particles" : "") << ", stereo " << int(mode)
              << ", frame " << f;
        EXPECT_LE(on.drawn, off.drawn) << name;
        if (v == 1) {
          ++inside_views;
          inside_views_culled += on.drawn < off.drawn;
        }
      }
  }
  EXPECT_GE(scenes, 10u);
  // From among the particles, most scenes' lists lose some: the comparison is not vacuous.
  EXPECT_GE(inside_views_culled * 3, inside_views * 2);
}

}  // namespace
}  // namespace pyro
