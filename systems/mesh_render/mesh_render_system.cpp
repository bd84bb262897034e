#include "systems/mesh_render/mesh_render_system.h"

#include "components/gpu_frame.h"
#include "components/mesh_instance.h"
#include "components/render_settings.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/mesh_render/mesh_renderer.h"

namespace pyro {

ecs::SystemDesc mesh_render_system() {
  return {"mesh_render", ecs::Phase::render, ecs::access<MeshInstance, View, RenderSettings>(),
          ecs::access<GpuFrame>(), [](ecs::World& world) {
            if (!world.has_resource<MeshRenderer>()) world.set_resource<MeshRenderer>();
            std::vector<MeshInstance> instances;
            world.each<MeshInstance>([&](MeshInstance& m) { instances.push_back(m); });
            const View& view = world.resource<View>();
            GpuFrame& frame = world.resource<GpuFrame>();
            for (size_t v = 0; v < view.eyes.size() && v < frame.eyes.size(); ++v) {
              world.resource<MeshRenderer>().draw(instances, view.eyes[v],
                                                  world.resource<RenderSettings>(),
                                                  *frame.eyes[v].scene);
            }
          }};
}

}  // namespace pyro
