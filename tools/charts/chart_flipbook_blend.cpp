// pyro chart flipbook-blend: playing a baked flame flipbook between its frames, by the linear
// cross-fade and by the motion-vector blend (systems/flipbook_fire/flipbook_motion_blend.h), each
// against the true in-between frame. For n frames per loop (the loop's duration fixed), the fire
// scene is baked as an atlas with motion vectors (pyro bake-flipbook --atlas, without the loop's
// cross-fade) at 2n frames per loop: its even frames are the n-frame flipbook (motion over one of
// its frames: twice the baked motion over one step), its odd frames the truth at the half step.
// By default without the bake's border fade: the chart compares ways of moving the medium between
// frames, and the fade is a window fixed to the frame that the medium moves under.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/scratch_folder.h"
#include "engine/math/color.h"
#include "tools/charts/charts.h"
#include "systems/flipbook_fire/flipbook_atlas_folder.h"
#include "systems/flipbook_fire/flipbook_motion_blend.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/open_scene/flipbook_bake.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

// Frame RGB in linear light.
BlendImage linear_rgb(const FlipbookFrames& f, size_t frame) {
  BlendImage image{f.width, f.height, 3, std::vector<float>(static_cast<size_t>(f.width) * f.height * 3)};
  const std::vector<uint8_t>& rgba = f.rgba[frame];
  for (size_t i = 0; i < image.values.size() / 3; ++i)
    for (size_t c = 0; c < 3; ++c) image.values[i * 3 + c] = srgb_to_linear(rgba[i * 4 + c] / 255.0f);
  return image;
}

MotionField doubled(MotionField m) {
  for (float& x : m.uv) x *= 2.0f;
  return m;
}

struct BlendErrors {
  double linear = 0.0, motion = 0.0;  // RMSE over every in-between frame
  double seconds = 0.0;               // the bake
};

BlendErrors measure(const SceneDescription& base, const FlipbookBlendChartOptions& o, int frames,
                    const fs::path& folder) {
  SceneDescription scene = base;
  scene.frames_per_second = static_cast<float>(2 * frames / o.loop_seconds);
  FlipbookBakeOptions bake;
  bake.frames = 2 * frames;
  bake.loop_blend = 0;
  bake.width = o.width;
  bake.height = o.height;
  bake.atlas_columns = 8;
  bake.atlas_rows = (bake.frames + 7) / 8;
  if (!o.border_fade) bake.fade = {0.0f, 0.0f, 0.0f};
  BlendErrors e;
  e.seconds = bake_flipbook(scene, bake, folder.string()).seconds;
  const FlipbookFrames f = read_flipbook_atlas(folder.string());
  double linear = 0.0, motion = 0.0;
  int pairs = 0;
  for (size_t j = 0; j + 2 < f.rgba.size(); j += 2, ++pairs) {
    const BlendImage a = linear_rgb(f, j), truth = linear_rgb(f, j + 1), b = linear_rgb(f, j + 2);
    linear += std::pow(rmse(blend_linear(a, b, 0.5f), truth), 2.0);
    motion += std::pow(rmse(blend_motion_vectors(a, doubled(f.motion[j]), b, doubled(f.motion[j + 2]), 0.5f), truth), 2.0);
  }
  e.linear = std::sqrt(linear / pairs);
  e.motion = std::sqrt(motion / pairs);
  return e;
}

}  // namespace

ChartTable chart_flipbook_blend(const FlipbookBlendChartOptions& o) {
  const SceneDescription scene = load_scene(o.scene.empty() ? content_path("scenes/flipbook_fire.json") : o.scene);
  ChartTable t;
  t.name = "flipbook-blend";
  t.title = "Flipbook in-between frames: linear against motion-vector blending (" + std::to_string(o.width) +
            "x" + std::to_string(o.height) + ")";
  t.x_label = "frames per loop (the loop's duration fixed)";
  t.y_label = "RMSE (linear RGB) against the true half-step frame";
  t.ground_truth = "the simulation rendered at the half step (a bake at twice the frames: its odd frames)";
  t.notes = {"loop " + std::to_string(o.loop_seconds) + " s; in-betweens at t = 0.5 between every pair of frames",
             "motion vectors as the atlas stores them (8-bit, strength from the sidecar)",
             o.border_fade ? "frames faded at the borders as the bake fades them"
                           : "frames without the bake's border fade (a window fixed to the frame, not carried by the medium)"};
  ScratchFolder scratch("pyro-flipbook-blend");
  nlohmann::json summary = nlohmann::json::array();
  for (int frames : o.frames_per_loop) {
    const BlendErrors e = measure(scene, o, frames, scratch.path / std::to_string(frames));
    const std::string n = std::to_string(frames);
    t.rows.push_back({"linear " + n, "linear", double(frames), e.linear, {e.seconds}, false, true, "linear"});
    t.rows.push_back({"motion vectors " + n, "motion vectors", double(frames), e.motion, {e.seconds}, false, true,
                      "motion vectors"});
    summary.push_back({{"frames_per_loop", frames}, {"linear_rmse", e.linear}, {"motion_vector_rmse", e.motion}});
  }
  t.extra_columns = {"bake_seconds"};
  t.summary["errors"] = summary;
  mark_pareto_front(t);
  return t;
}

}  // namespace pyro
