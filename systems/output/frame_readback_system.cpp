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

bool layered(const EyeTargets& eye) { return eye.layer || eye.media_atlas; }

// A linear float target the size of `eye`'s scene target, in the LinearResolveTarget resource.
const gpu::RenderTarget& resolve_target(ecs::World& world, const EyeTargets& eye) {
  LinearResolveTarget& r = world.resource<LinearResolveTarget>();
  const int w = eye.scene->width(), h = eye.scene->height();
  if (!r.target || r.target->width() != w || r.target->height() != h)
    r.target = std::make_unique<gpu::RenderTarget>(w, h, GL_RGBA32F);
  return *r.target;
}

void read_back(ecs::World& world) {
  const GpuFrame& frame = world.resource<const GpuFrame>();
  FrameImage& image = world.resource<FrameImage>();
  for (size_t v = 0; v < frame.eyes.size(); ++v) {
    const EyeTargets& eye = frame.eyes[v];
    std::vector<float>& out = v == 0 ? image.rgba : image.right_rgba;
    if (!layered(eye)) {
      out = eye.scene->read_rgba();
      continue;
    }
    // The final composition folds the layer in on the fly; resolve the same arithmetic into a
    // linear float target to read it.
    const gpu::RenderTarget& resolve = resolve_target(world, eye);
    world.resource<Compositor>().resolve_linear(eye, resolve);
    out = resolve.read_rgba();
  }
  image.width = frame.eyes[0].scene->width();
  image.height = frame.eyes[0].scene->height();
  image.valid = true;
}

void make_readback_resources(ecs::World& world) {
  if (!world.has_resource<FrameImage>()) world.set_resource<FrameImage>();
  if (!world.has_resource<Compositor>()) world.set_resource<Compositor>();
  if (!world.has_resource<LinearResolveTarget>()) world.set_resource<LinearResolveTarget>();
  const GpuFrame* frame = world.try_resource<const GpuFrame>();
  if (frame && !frame->eyes.empty() && layered(frame->eyes[0]))
    resolve_target(world, frame->eyes[0]);
}

}  // namespace

ecs::SystemDesc frame_readback_system() {
  return {.name = "frame_readback",
          .phase = ecs::Phase::output,
          .access = ecs::Access::of<ecs::Reads<GpuFrame>,
                                    ecs::Writes<FrameImage, Compositor, LinearResolveTarget>>(),
          .run = read_back,
          .setup = make_readback_resources,
          .main_thread = true};
}

}  // namespace pyro
