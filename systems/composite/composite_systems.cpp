#include "systems/composite/composite_systems.h"

#include "components/explosion_shading.h"
#include "components/frame_clock.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "engine/ecs/world.h"
#include "systems/composite/compositor.h"

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

void composite(ecs::World& world) {
  GpuFrame& frame = world.resource<GpuFrame>();
  Compositor& compositor = world.resource<Compositor>();
  if (!frame.eyes.empty() && frame.eyes[0].media_atlas)
    compositor.set_media(media_composition(world));
  bool swap_eyes = false;
  bool found = false;
  world.each<const StereoCamera>([&](const StereoCamera& s) {
    if (!found) swap_eyes = s.eye_order == EyeOrder::right_left;
    found = true;
  });
  const RenderSettings& settings = world.resource<const RenderSettings>();
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
                                               ExplosionShading, MediaComposition>,
                                    ecs::Writes<GpuFrame, Compositor>>(),
          .run = composite,
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<Compositor>()) world.set_resource<Compositor>();
              },
          .main_thread = true};
}

}  // namespace pyro
