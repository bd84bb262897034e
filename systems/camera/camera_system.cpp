#include "systems/camera/camera_system.h"

#include "components/camera.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/camera/camera_views.h"

namespace pyro {

ecs::SystemDesc stereo_camera_system() {
  return {
      .name = "stereo_camera",
      .phase = ecs::Phase::camera,
      .access =
          ecs::Access::of<ecs::Reads<Camera, StereoCamera, RenderSettings>, ecs::Writes<View>>(),
      .run =
          [](ecs::World& world) {
            const RenderSettings& settings = world.resource<const RenderSettings>();
            View& view = world.resource<View>();
            bool found = false;
            world.each<const Camera>([&](ecs::Entity e, const Camera& c) {
              if (found) return;  // the first camera renders
              view.frame = mono_frame(c, settings);
              view.eyes = rendered_views(c, world.try_get<const StereoCamera>(e), settings);
              found = true;
            });
          },
      .setup =
          [](ecs::World& world) {
            if (!world.has_resource<View>()) world.set_resource<View>();
          }};
}

}  // namespace pyro
