#include "systems/output/frame_readback_system.h"

#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "engine/ecs/world.h"

namespace pyro {

ecs::SystemDesc frame_readback_system() {
  return {"readback", ecs::Phase::output, ecs::access<GpuFrame>(), ecs::access<FrameImage>(),
          [](ecs::World& world) {
            // The first view's composited scene, linear: what image tests compare.
            const gpu::RenderTarget& target = *world.resource<GpuFrame>().eyes.at(0).scene;
            FrameImage& image = world.has_resource<FrameImage>() ? world.resource<FrameImage>()
                                                                 : world.set_resource<FrameImage>();
            image.width = target.width();
            image.height = target.height();
            image.rgba = target.read_rgba();
            image.valid = true;
          }};
}

}  // namespace pyro
