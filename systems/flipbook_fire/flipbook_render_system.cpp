#include "systems/flipbook_fire/flipbook_render_system.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "components/flipbook_draw_list.h"
#include "components/flipbook_fire.h"
#include "components/frame_clock.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "engine/math/flipbook_sequence.h"
#include "systems/flipbook_fire/flipbook_geometry.h"
#include "systems/flipbook_fire/flipbook_renderer.h"
#include "systems/lighting/light_buffer.h"

namespace pyro {

namespace {

void orient_flipbook_fires(ecs::World& world) {
  const View* view = world.try_resource<const View>();
  if (!view) return;
  FlipbookDrawList& list = world.resource<FlipbookDrawList>();
  list.fires.clear();
  const FrameClock* clock = world.try_resource<const FrameClock>();
  const double time = clock ? clock->time() : 0.0;
  // One orientation per fire for every eye: from the mid-eye point.
  list.viewer = view->frame.eye;
  world.each<const FlipbookFire>([&](const FlipbookFire& fire) {
    if (fire.frame_count <= 0 || fire.texture < 0) return;
    FlipbookDrawList::Fire f;
    f.frame = face_viewer(fire.position, fire.up, list.viewer, -view->frame.forward);
    const int64_t step = flipbook_step(time, fire.frames_per_second);
    // Between steps only where motion vectors carry the flame there; else the step's frame.
    const float fraction =
        fire.motion_vectors
            ? std::clamp(static_cast<float>(time * fire.frames_per_second - static_cast<double>(step)), 0.0f, 1.0f)
            : 0.0f;
    f.quads = flipbook_quads(fire, f.frame, step, fire.frame_count, fraction);
    // The flame puffs with its light (systems/lighting/flipbook_fire_lights.h).
    const float flicker = static_cast<float>(flame_flicker(flicker_of(fire), time));
    for (FlipbookQuad& q : f.quads) q.intensity *= flicker;
    f.texture = fire.texture;
    f.blend = fire.blend;
    f.distance = glm::length(fire.position - list.viewer);
    list.fires.push_back(std::move(f));
  });
  std::stable_sort(list.fires.begin(), list.fires.end(),
                   [](const FlipbookDrawList::Fire& a, const FlipbookDrawList::Fire& b) {
                     return a.distance > b.distance;
                   });
}

void draw_flipbook_fires(ecs::World& world) {
  FlipbookRenderer* renderer = world.try_resource<FlipbookRenderer>();
  const View* view = world.try_resource<const View>();
  const FlipbookDrawList* list = world.try_resource<const FlipbookDrawList>();
  if (!renderer || !view || !list || list->fires.empty()) return;
  GpuFrame& targets = world.resource<GpuFrame>();
  const LightBuffer& lights = world.resource<const LightBuffer>();
  for (size_t v = 0; v < view->eyes.size() && v < targets.eyes.size(); ++v)
    for (const FlipbookDrawList::Fire& f : list->fires)
      renderer->draw(f.quads, f.texture, f.blend, f.frame, lights, view->eyes[v], *targets.eyes[v].scene);
}

}  // namespace

ecs::SystemDesc flipbook_orient_system() {
  return {.name = "flipbook_orient",
          .phase = ecs::Phase::sort,
          .access = ecs::Access::of<ecs::Reads<FlipbookFire, View, FrameClock>,
                                    ecs::Writes<FlipbookDrawList>>(),
          .run = orient_flipbook_fires,
          .setup = [](ecs::World& world) {
            if (!world.has_resource<FlipbookDrawList>()) world.set_resource<FlipbookDrawList>();
          }};
}

ecs::SystemDesc flipbook_render_system() {
  return {.name = "flipbook_render",
          .phase = ecs::Phase::render,
          .access = ecs::Access::of<ecs::Reads<FlipbookDrawList, View, LightBuffer>,
                                    ecs::Writes<GpuFrame, FlipbookRenderer>>(),
          .run = draw_flipbook_fires,
          // The opaque pass clears and fills the scene targets this pass blends into.
          .after = {"mesh_render"},
          .main_thread = true};
}

}  // namespace pyro
