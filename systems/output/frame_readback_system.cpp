#include "systems/output/frame_readback_system.h"

#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "engine/ecs/world.h"
#include "systems/composite/compositor.h"

namespace pyro {

namespace {
// Scratch target for resolving a layered view to linear floats.
struct LinearResolveTarget {
  std::unique_ptr<gpu::RenderTarget> target;
};
}  // namespace

ecs::SystemDesc frame_readback_system() {
  return {"readback", ecs::Phase::output, ecs::access<GpuFrame>(), ecs::access<FrameImage>(),
          [](ecs::World& world) {
            GpuFrame& frame = world.resource<GpuFrame>();
            FrameImage& image = world.has_resource<FrameImage>() ? world.resource<FrameImage>()
                                                                 : world.set_resource<FrameImage>();
            for (size_t v = 0; v < frame.eyes.size(); ++v) {
              EyeTargets& eye = frame.eyes[v];
              std::vector<float>& out = v == 0 ? image.rgba : image.right_rgba;
              if (!eye.layer && !eye.media_atlas) {
                out = eye.scene->read_rgba();
                continue;
              }
              // The final composition folds the layer in on the fly; resolve the same
              // arithmetic into a linear float target to read it.
              if (!world.has_resource<Compositor>()) world.set_resource<Compositor>();
              if (!world.has_resource<LinearResolveTarget>() ||
                  world.resource<LinearResolveTarget>().target->width() != eye.scene->width() ||
                  world.resource<LinearResolveTarget>().target->height() != eye.scene->height()) {
                world.set_resource<LinearResolveTarget>(LinearResolveTarget{
                    std::make_unique<gpu::RenderTarget>(eye.scene->width(), eye.scene->height(), GL_RGBA32F)});
              }
              const gpu::RenderTarget& resolve = *world.resource<LinearResolveTarget>().target;
              world.resource<Compositor>().resolve_linear(eye, resolve);
              out = resolve.read_rgba();
            }
            image.width = frame.eyes[0].scene->width();
            image.height = frame.eyes[0].scene->height();
            image.valid = true;
          }};
}

}  // namespace pyro
