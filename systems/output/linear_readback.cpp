#include "systems/output/linear_readback.h"

#include <limits>
#include <memory>

#include "components/gpu_frame.h"
#include "components/view.h"
#include "engine/math/camera_math.h"
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

std::vector<float> read_color(ecs::World& world, const EyeTargets& eye) {
  if (!layered(eye)) return eye.scene->read_rgba();
  // The final composition folds the layer in on the fly; resolve the same arithmetic into a
  // linear float target to read it.
  const gpu::RenderTarget& resolve = resolve_target(world, eye);
  world.resource<Compositor>().resolve_linear(eye, resolve);
  return resolve.read_rgba();
}

// Window depths to view depths; the cleared far plane (d = 1: no geometry) to +infinity.
std::vector<float> read_view_depth(const EyeTargets& eye, const CameraFrame& camera) {
  std::vector<float> depth = eye.scene->read_depth();
  for (float& d : depth)
    d = d >= 1.0f ? std::numeric_limits<float>::infinity()
                  : window_to_view_depth(d, camera.near, camera.far);
  return depth;
}

}  // namespace

void make_linear_readback_resources(ecs::World& world) {
  if (!world.has_resource<Compositor>()) world.set_resource<Compositor>();
  if (!world.has_resource<LinearResolveTarget>()) world.set_resource<LinearResolveTarget>();
  const GpuFrame* frame = world.try_resource<const GpuFrame>();
  if (frame && !frame->eyes.empty() && layered(frame->eyes[0]))
    resolve_target(world, frame->eyes[0]);
}

void declare_linear_readback_access(ecs::Access& access, bool with_depth) {
  access.read<GpuFrame>().write<Compositor>().write<LinearResolveTarget>();
  if (with_depth) access.read<View>();
}

std::vector<LinearView> read_linear_views(ecs::World& world, bool with_depth) {
  make_linear_readback_resources(world);
  const GpuFrame& frame = world.resource<const GpuFrame>();
  std::vector<LinearView> views;
  for (size_t v = 0; v < frame.eyes.size(); ++v) {
    const EyeTargets& eye = frame.eyes[v];
    LinearView view{eye.scene->width(), eye.scene->height(), read_color(world, eye), {}};
    if (with_depth) view.depth = read_view_depth(eye, world.resource<const View>().eyes.at(v));
    views.push_back(std::move(view));
  }
  return views;
}

}  // namespace pyro
