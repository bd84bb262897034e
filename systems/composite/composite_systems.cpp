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
            const GpuFrame& frame = world.resource<GpuFrame>();
            compositor(world).compose(world.resource<RenderSettings>().stereo_mode, frame);
            if (frame.display) {
              // The frame-scale shortcut: upscale the composed image bilinearly.
              const gpu::RenderTarget& from = *frame.output;
              const gpu::RenderTarget& to = *frame.display;
              glBlitNamedFramebuffer(from.framebuffer(), to.framebuffer(), 0, 0, from.width(),
                                     from.height(), 0, 0, to.width(), to.height(),
                                     GL_COLOR_BUFFER_BIT, GL_LINEAR);
            }
          }};
}

}  // namespace pyro
