#include "systems/camera/camera_system.h"

#include "components/camera.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "components/view.h"
#include "engine/ecs/world.h"
#include "systems/camera/camera_views.h"

namespace pyro {

ecs::SystemDesc camera_system() {
  return {"camera", ecs::Phase::camera, ecs::access<Camera, StereoCamera, RenderSettings>(),
          ecs::access<View>(), [](ecs::World& world) {
            const RenderSettings& settings = world.resource<RenderSettings>();
            View& view = world.has_resource<View>() ? world.resource<View>() : world.set_resource<View>();
            bool found = false;
            world.each<Camera>([&](ecs::Entity e, Camera& c) {
              if (found) return;  // the first camera renders
              view.frame = mono_frame(c, settings);
              view.eyes = rendered_views(c, world.try_get<StereoCamera>(e), settings);
              found = true;
            });
          }};
}

}  // namespace pyro
