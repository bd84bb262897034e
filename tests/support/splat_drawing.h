#pragma once
// For tests that draw the Gaussian splats of shipped scenes through the billboard renderer: the
// shipped scenes whose particles are splats, and one draw list drawn into a fresh, cleared
// target, read back.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "components/draw_list.h"
#include "engine/core/content_path.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/runtime/scene/scene_loader.h"

namespace pyro::test {

// The shipped scenes (file names under content/scenes) whose particles are isotropic Gaussian
// splats: clouds, or volumes imported from a .vdb on load (a shipped .pyrop holds anisotropic
// particles, drawn by their own renderer).
inline std::vector<std::string> gaussian_scenes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(content_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    const SceneDescription scene = load_scene(entry.path().string());
    const bool vdb = std::any_of(scene.volumes.begin(), scene.volumes.end(), [](const auto& v) {
      return std::filesystem::path(v.file).extension() == ".vdb";
    });
    if (scene.render.particles == ParticleShape::gaussian && (!scene.clouds.empty() || vdb))
      names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// `list` drawn for `frame` into a width x height target cleared to transparent black.
inline std::vector<float> draw_into_fresh_target(BillboardRenderer& renderer, const DrawList& list,
                                                 const std::vector<const ParticlePool*>& pools,
                                                 const CameraFrame& frame, int width, int height) {
  gpu::RenderTarget target(width, height);
  target.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(list, pools, frame, target);
  return target.read_rgba();
}

}  // namespace pyro::test
