#include "systems/flipbook_fire/flipbook_render_system.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "components/flipbook_fire.h"
#include "components/frame_clock.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "engine/math/flipbook_sequence.h"
#include "systems/flipbook_fire/flipbook_geometry.h"
#include "systems/flipbook_fire/flipbook_renderer.h"

namespace pyro {

ecs::SystemDesc flipbook_render_system() {
  return {"flipbook_render", ecs::Phase::render,
          ecs::access<FlipbookFire, View, FrameClock, FlipbookRenderer>(), ecs::access<GpuFrame>(),
          [](ecs::World& world) {
            FlipbookRenderer* renderer = world.try_resource<FlipbookRenderer>();
            const View* view = world.try_resource<View>();
            if (!renderer || !view) return;
            const FrameClock* clock = world.try_resource<FrameClock>();
            const double time = clock ? clock->time() : 0.0;
            // One orientation per fire for every eye: from the mid-eye point.
            const glm::vec3 mid_eye = view->frame.eye;
            struct Drawn {
              float distance;
              std::vector<FlipbookQuad> quads;
              int texture;
              FlipbookBlend blend;
            };
            std::vector<Drawn> fires;
            world.each<FlipbookFire>([&](FlipbookFire& fire) {
              if (fire.frame_count <= 0 || fire.texture < 0) return;
              const FireFrame frame = face_viewer(fire.position, fire.up, mid_eye, -view->frame.forward);
              const int64_t step = flipbook_step(time, fire.frames_per_second);
              fires.push_back({glm::length(fire.position - mid_eye),
                               flipbook_quads(fire, frame, step, fire.frame_count), fire.texture,
                               fire.blend});
            });
            if (fires.empty()) return;
            std::stable_sort(fires.begin(), fires.end(),
                             [](const Drawn& a, const Drawn& b) { return a.distance > b.distance; });
            GpuFrame& targets = world.resource<GpuFrame>();
            for (size_t v = 0; v < view->eyes.size() && v < targets.eyes.size(); ++v)
              for (const Drawn& d : fires)
                renderer->draw(d.quads, d.texture, d.blend, view->eyes[v], *targets.eyes[v].scene);
          }};
}

}  // namespace pyro
