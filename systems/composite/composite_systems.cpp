#include "systems/composite/composite_systems.h"

#include "components/gpu_frame.h"
#include "components/render_settings.h"
#include "engine/ecs/world.h"
#include "systems/composite/compositor.h"

namespace pyro {

namespace {
Compositor& compositor(ecs::World& world) {
  if (!world.has_resource<Compositor>()) world.set_resource<Compositor>();
  return world.resource<Compositor>();
}
}  // namespace

ecs::SystemDesc stereo_compose_system() {
  return {"composite", ecs::Phase::composite, ecs::access<GpuFrame, RenderSettings>(),
          ecs::access<GpuFrame>(), [](ecs::World& world) {
            compositor(world).compose(world.resource<RenderSettings>().stereo_mode,
                                      world.resource<GpuFrame>());
          }};
}

}  // namespace pyro
