#include "systems/billboard_render/billboard_render_system.h"

#include "components/draw_list.h"
#include "components/gpu_frame.h"
#include "components/render_settings.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/billboard_render/billboard_renderer.h"

namespace pyro {

void draw_particles_for_view(BillboardRenderer& renderer, const DrawList& list,
                             const CameraFrame& frame, EyeTargets& targets,
                             BillboardAlignment alignment, BillboardShading shading) {
  if (!targets.layer) {
    renderer.draw(list, frame, *targets.scene, alignment, shading);
    return;
  }
  // Reduced resolution (Umenhoffer et al. 2006, section 4): the layer starts transparent, with
  // the scene's depth point-sampled down so opaque geometry still hides particles.
  const gpu::RenderTarget& scene = *targets.scene;
  const gpu::RenderTarget& layer = *targets.layer;
  glBlitNamedFramebuffer(scene.framebuffer(), layer.framebuffer(), 0, 0, scene.width(),
                         scene.height(), 0, 0, layer.width(), layer.height(),
                         GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(layer.framebuffer(), GL_COLOR, 0, clear);
  renderer.draw(list, frame, layer, alignment, shading);
}

ecs::SystemDesc billboard_render_system() {
  return {"billboard_render", ecs::Phase::render,
          ecs::access<EyeDrawLists, View, RenderSettings>(), ecs::access<GpuFrame>(),
          [](ecs::World& world) {
            const EyeDrawLists* lists = world.try_resource<EyeDrawLists>();
            if (!lists) return;
            const View& view = world.resource<View>();
            GpuFrame& frame = world.resource<GpuFrame>();
            const BillboardAlignment alignment = world.resource<RenderSettings>().alignment;
            BillboardRenderer& renderer = world.resource<BillboardRenderer>();
            for (size_t v = 0; v < view.eyes.size() && v < frame.eyes.size() && v < lists->eyes.size(); ++v)
              draw_particles_for_view(renderer, lists->eyes[v], view.eyes[v], frame.eyes[v], alignment,
                                      BillboardShading::kernel);
          }};
}

}  // namespace pyro
