#include "systems/mesh_render/mesh_render_system.h"

#include "components/gpu_frame.h"
#include "components/mesh_instance.h"
#include "components/mesh_shadow.h"
#include "components/render_settings.h"
#include "components/shadow_volume.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/lighting/light_buffer.h"
#include "systems/mesh_render/mesh_renderer.h"

namespace pyro {

ecs::SystemDesc mesh_render_system() {
  return {
      .name = "mesh_render",
      .phase = ecs::Phase::render,
      .access = ecs::Access::of<ecs::Reads<MeshInstance, View, RenderSettings, LightBuffer, ShadowVolume, MeshShadow>,
                                ecs::Writes<GpuFrame, MeshRenderer>>(),
      .run =
          [](ecs::World& world) {
            std::vector<MeshInstance> instances;
            world.each<const MeshInstance>([&](const MeshInstance& m) { instances.push_back(m); });
            const View& view = world.resource<const View>();
            const RenderSettings& settings = world.resource<const RenderSettings>();
            const LightBuffer& lights = world.resource<const LightBuffer>();
            const ShadowVolume* shadows = world.try_resource<const ShadowVolume>();
            const MeshShadow* mesh_shadow = world.try_resource<const MeshShadow>();
            MeshRenderer& renderer = world.resource<MeshRenderer>();
            GpuFrame& frame = world.resource<GpuFrame>();
            for (size_t v = 0; v < view.eyes.size() && v < frame.eyes.size(); ++v) {
              const int before = renderer.meshes_drawn() + renderer.images_restored();
              renderer.draw(instances, view.eyes[v], settings, lights, *frame.eyes[v].scene, shadows, mesh_shadow);
              if (renderer.meshes_drawn() + renderer.images_restored() != before)
                ++frame.eyes[v].opaque_version;
            }
          },
      .setup =
          [](ecs::World& world) {
            if (!world.has_resource<MeshRenderer>()) world.set_resource<MeshRenderer>();
          },
      // The first to draw: after the lights are on the GPU.
      .after = {"light_upload"},
      .main_thread = true};
}

}  // namespace pyro
