#pragma once
// A scene brought to life: the world built from a SceneDescription (a camera entity, one entity
// per cloud and per mesh, the resources) and the standard schedule of systems:
//   spawn:     emitter
//   simulate:  animation, camera_orbit
//   sort:      sorting
//   camera:    camera
//   render:    mesh_render, billboard_render
//   output:    readback (optional)
// Frame f shows the state after f simulation steps of dt = 1 / fps.
#include <memory>
#include <string>

#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "engine/gpu/gl_context.h"
#include "engine/io/scene_description.h"

namespace pyro {

struct FrameImage;

struct RuntimeOptions {
  bool readback = true;     // read each frame back into the FrameImage resource
  int width_override = 0;   // > 0: replaces the scene's output size
  int height_override = 0;
};

// The process-wide headless context (made on first use).
gpu::HeadlessContext& shared_headless_context();

class SceneRuntime {
 public:
  explicit SceneRuntime(const SceneDescription& scene, const RuntimeOptions& options = {});

  // Runs every system once for the current frame, then advances the clock.
  void step();
  uint64_t frame() const;

  ecs::World& world() { return world_; }
  const ecs::Schedule& schedule() const { return schedule_; }
  const SceneDescription& scene() const { return scene_; }
  // The last frame read back (requires options.readback).
  const FrameImage& image();
  // Writes the last frame as an sRGB PNG (temporary name, then renamed).
  void write_png(const std::string& path);

 private:
  SceneDescription scene_;
  ecs::World world_;
  ecs::Schedule schedule_;
};

}  // namespace pyro
