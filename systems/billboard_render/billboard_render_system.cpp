#include "systems/billboard_render/billboard_render_system.h"

#include "components/draw_list.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/billboard_render/billboard_renderer.h"

namespace pyro {

ecs::SystemDesc billboard_render_system() {
  return {"billboard_render", ecs::Phase::render, ecs::access<DrawList, View>(),
          ecs::access<GpuFrame>(), [](ecs::World& world) {
            const DrawList* list = world.try_resource<DrawList>();
            if (!list) return;
            world.resource<BillboardRenderer>().draw(*list, world.resource<View>().frame,
                                                     *world.resource<GpuFrame>().target);
          }};
}

}  // namespace pyro
