#include "systems/camera/camera_system.h"

#include "components/camera.h"
#include "components/render_settings.h"
#include "components/view.h"
#include "engine/ecs/world.h"

namespace pyro {

ecs::SystemDesc camera_system() {
  return {"camera", ecs::Phase::camera, ecs::access<Camera, RenderSettings>(), ecs::access<View>(),
          [](ecs::World& world) {
            const RenderSettings& settings = world.resource<RenderSettings>();
            View& view = world.has_resource<View>() ? world.resource<View>() : world.set_resource<View>();
            bool found = false;
            world.each<Camera>([&](Camera& c) {
              if (found) return;
              view.frame = make_camera_frame(c.position, c.target, c.up, c.fov_y_deg, c.near, c.far,
                                             settings.width, settings.height);
              found = true;
            });
          }};
}

}  // namespace pyro
