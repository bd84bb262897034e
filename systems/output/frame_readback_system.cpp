#include "systems/output/frame_readback_system.h"

#include "components/frame_image.h"
#include "engine/ecs/world.h"
#include "systems/output/linear_readback.h"

namespace pyro {

namespace {

void read_back(ecs::World& world) {
  std::vector<LinearView> views = read_linear_views(world, false);
  FrameImage& image = world.resource<FrameImage>();
  image.rgba = std::move(views[0].rgba);
  image.right_rgba = views.size() > 1 ? std::move(views[1].rgba) : std::vector<float>{};
  image.width = views[0].width;
  image.height = views[0].height;
  image.valid = true;
}

void make_readback_resources(ecs::World& world) {
  if (!world.has_resource<FrameImage>()) world.set_resource<FrameImage>();
  make_linear_readback_resources(world);
}

}  // namespace

ecs::SystemDesc frame_readback_system() {
  ecs::Access access = ecs::Access::of<ecs::Writes<FrameImage>>();
  declare_linear_readback_access(access, false);
  return {.name = "frame_readback",
          .phase = ecs::Phase::output,
          .access = access,
          .run = read_back,
          .setup = make_readback_resources,
          .main_thread = true};
}

}  // namespace pyro
