#include "systems/composite/composite_systems.h"

#include "components/draw_list.h"
#include "components/explosion_shading.h"
#include "components/frame_clock.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "engine/ecs/world.h"
#include "systems/composite/compositor.h"
#include "systems/composite/particle_depth_grid.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec2.hpp>

namespace pyro {

namespace {

// The explosion's media layers: the composition's per-frame inputs (depth range, time, shimmer)
// and, from the MediaComposition resource when there is one, how the layers are upsampled.
MediaComposition media_composition(const ecs::World& world) {
  MediaComposition m;
  if (const View* view = world.try_resource<View>(); view && !view->eyes.empty()) {
    m.near = view->eyes[0].near;
    m.far = view->eyes[0].far;
  }
  if (const FrameClock* clock = world.try_resource<FrameClock>())
    m.time = static_cast<float>(clock->time());
  const ExplosionShading* shading = world.try_resource<ExplosionShading>();
  m.shimmer = shading ? shading->shimmer : ExplosionShading{}.shimmer;
  if (const MediaComposition* over = world.try_resource<MediaComposition>()) {
    m.depth_aware = over->depth_aware;
    m.depth_tolerance = over->depth_tolerance;
    m.tiles = over->tiles;
  }
  return m;
}

// Each view's particle depth grid (particle_depth_grid.h) into EyeTargets::particle_depths, as
// 1/z at its far and near end (from the near plane on); a cell no particle reaches gets one value,
// so that every depth clamps alike there. Without a draw list nothing is known: every cell spans
// all depths. Only depth-aware upsampling of reduced layers reads them: otherwise nothing is made.
void upload_particle_depths(const ecs::World& world, GpuFrame& frame, const MediaComposition& m) {
  const float near = m.near;
  const EyeDrawLists* lists = world.try_resource<EyeDrawLists>();
  const View* view = world.try_resource<View>();
  for (size_t v = 0; v < frame.eyes.size(); ++v) {
    EyeTargets& eye = frame.eyes[v];
    if (!eye.particle_depths || !m.depth_aware) continue;
    const bool reduced = eye.media_combined->width() != eye.scene->width() ||
                         eye.media_combined->height() != eye.scene->height();
    if (!reduced) continue;
    const glm::ivec2 size(eye.scene->width(), eye.scene->height());
    // A layer texel in view pixels, and one for rounding (particle_depth_grid.h).
    const float reach = static_cast<float>(eye.scene->width()) / eye.media_combined->width() +
                        static_cast<float>(eye.scene->height()) / eye.media_combined->height() +
                        1.0f;
    ParticleDepthGrid grid;
    if (lists && view && v < lists->eyes.size() && v < view->eyes.size()) {
      grid = particle_depth_grid(lists->eyes[v], view->eyes[v], size, reach);
    } else {
      grid.cells = particle_depth_cells(size);
      grid.ranges.assign(static_cast<size_t>(grid.cells.x) * grid.cells.y, {0.0f, INFINITY});
    }
    std::vector<glm::vec2> texels(grid.ranges.size());
    for (size_t i = 0; i < texels.size(); ++i) {
      const ParticleDepthRange& r = grid.ranges[i];
      const float lo = std::max(r.near, near);
      texels[i] = lo > r.far ? glm::vec2(1.0f) : glm::vec2(1.0f / r.far, 1.0f / lo);
    }
    glTextureSubImage2D(eye.particle_depths.get(), 0, 0, 0, grid.cells.x, grid.cells.y, GL_RG,
                        GL_FLOAT, texels.data());
  }
}

void composite(ecs::World& world) {
  GpuFrame& frame = world.resource<GpuFrame>();
  Compositor& compositor = world.resource<Compositor>();
  if (!frame.eyes.empty() && frame.eyes[0].media_atlas) {
    const MediaComposition m = media_composition(world);
    compositor.set_media(m);
    upload_particle_depths(world, frame, m);
  }
  bool swap_eyes = false;
  bool found = false;
  world.each<const StereoCamera>([&](const StereoCamera& s) {
    if (!found) swap_eyes = s.eye_order == EyeOrder::right_left;
    found = true;
  });
  const RenderSettings& settings = world.resource<const RenderSettings>();
  compositor.set_transparent(settings.transparent);
  compositor.compose(settings.stereo_mode, frame, swap_eyes, settings.motion_blur);
  if (frame.display) {
    // The frame-scale shortcut: upscale the composed image bilinearly.
    const gpu::RenderTarget& from = *frame.output;
    const gpu::RenderTarget& to = *frame.display;
    glBlitNamedFramebuffer(from.framebuffer(), to.framebuffer(), 0, 0, from.width(), from.height(),
                           0, 0, to.width(), to.height(), GL_COLOR_BUFFER_BIT, GL_LINEAR);
  }
}

}  // namespace

ecs::SystemDesc composite_system() {
  return {.name = "composite",
          .phase = ecs::Phase::composite,
          .access = ecs::Access::of<ecs::Reads<RenderSettings, StereoCamera, View, FrameClock,
                                               ExplosionShading, MediaComposition, EyeDrawLists>,
                                    ecs::Writes<GpuFrame, Compositor>>(),
          .run = composite,
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<Compositor>()) world.set_resource<Compositor>();
              },
          .main_thread = true};
}

}  // namespace pyro
