#include "systems/runtime/scene_runtime/standard_schedule.h"

#include <epoxy/gl.h>

#include <utility>

#include "engine/gpu/gpu_pass_timer.h"
#include "systems/animation/drift_system.h"
#include "systems/animation/particle_animation_system.h"
#include "systems/billboard_render/billboard_render_system.h"
#include "systems/camera/camera_system.h"
#include "systems/composite/composite_systems.h"
#include "systems/emitter/cloud_emitter_system.h"
#include "systems/emitter/emitter_system.h"
#include "systems/flipbook_fire/flipbook_render_system.h"
#include "systems/lighting/fire_lights.h"
#include "systems/lighting/light_animation.h"
#include "systems/lighting/light_block.h"
#include "systems/lighting/light_buffer.h"
#include "systems/lighting/lighting_system.h"
#include "systems/mesh_render/mesh_render_system.h"
#include "systems/output/frame_readback_system.h"
#include "systems/shadowing/mesh_shadow_map.h"
#include "systems/shadowing/shadowing_systems.h"
#include "systems/sorting/depth_sort.h"
#include "systems/volume_sequence/volume_sequence_system.h"

namespace pyro {

std::vector<ecs::SystemDesc> standard_systems(bool readback) {
  std::vector<ecs::SystemDesc> systems = {
      cloud_emitter_system(),   emitter_system(),          cloud_drift_system(),
      light_animation_system(), volume_sequence_system(),
      animation_system(),       lighting_system(),         mesh_shadow_system(),      shadow_map_system(),
      shadow_ray_system(),      fire_light_system(),       light_block_system(),
      camera_orbit_system(),    stereo_camera_system(),    sorting_system(),
      flipbook_orient_system(), light_upload_system(),     mesh_render_system(),     flipbook_render_system(),  billboard_render_system(),
      composite_system()};
  if (readback) systems.push_back(frame_readback_system());
  order_after_volume_sequence(systems);
  return systems;
}

ecs::Schedule standard_schedule(const RuntimeOptions& options) {
  ecs::Schedule schedule;
  schedule.set_threads(options.threads);
  std::vector<ecs::SystemDesc> systems = standard_systems(options.readback);
  systems.insert(systems.end(), options.extra_systems.begin(), options.extra_systems.end());
  for (ecs::SystemDesc& d : systems) {
    if (options.profile && d.main_thread) {
      // Systems that issue GL commands: their GPU time is a pass of its own on the GPU track.
      d.run = [run = std::move(d.run), name = d.name](ecs::World& w) {
        gpu::GpuPassScope pass(name.c_str());
        run(w);
      };
    }
    if (options.sync_timing && d.main_thread) {
      d.run = [run = std::move(d.run)](ecs::World& w) {
        run(w);
        glFinish();
      };
    }
    schedule.add(std::move(d));
  }
  return schedule;
}

}  // namespace pyro
