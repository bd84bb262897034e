#include "systems/output/frame_readback_system.h"

#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "engine/ecs/world.h"
#include "systems/composite/compositor.h"

namespace pyro {

ecs::SystemDesc frame_readback_system() {
  return {"readback", ecs::Phase::output, ecs::access<GpuFrame>(), ecs::access<FrameImage>(),
          [](ecs::World& world) {
            GpuFrame& frame = world.resource<GpuFrame>();
            FrameImage& image = world.has_resource<FrameImage>() ? world.resource<FrameImage>()
                                                                 : world.set_resource<FrameImage>();
            for (size_t v = 0; v < frame.eyes.size(); ++v) {
              EyeTargets& eye = frame.eyes[v];
              // The final composition folds the layer in on the fly; a linear copy of the view
              // needs it blended into the scene target first.
              if (eye.layer) {
                if (!world.has_resource<Compositor>()) world.set_resource<Compositor>();
                world.resource<Compositor>().upsample_layer(*eye.layer, *eye.scene);
              }
              (v == 0 ? image.rgba : image.right_rgba) = eye.scene->read_rgba();
            }
            image.width = frame.eyes[0].scene->width();
            image.height = frame.eyes[0].scene->height();
            image.valid = true;
          }};
}

}  // namespace pyro
