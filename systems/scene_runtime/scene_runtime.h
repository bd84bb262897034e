#pragma once
// A scene brought to life: the world built from a SceneDescription (a camera entity, one entity
// per cloud and per mesh, the resources) and the standard schedule of systems:
//   spawn:     emitter (clouds), particle_emitter (explosion emitters)
//   simulate:  animation (cloud drift), particle_animation (explosion particles), camera_orbit
//   sort:      sorting (one draw list per view)
//   camera:    camera (mono frame and eye frames)
//   render:    mesh_render, billboard_render (per view; particles into a layer when reduced)
//   composite: composite (particle layers over the scene, views into the output image)
//   output:    readback (optional: every view, linear, for tests and measurements)
// Frame f shows the state after f simulation steps of dt = 1 / fps (after prewarm + f steps when
// the scene asks for a prewarm: those steps run in the constructor). Both eyes of a stereo pair
// render the same simulation state: simulation runs once per frame.
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "components/render_settings.h"
#include "engine/core/trace_events.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "engine/gpu/gl_context.h"
#include "engine/gpu/gpu_pass_timer.h"
#include "engine/gpu/render_target.h"
#include "systems/scene/scene_description.h"

namespace pyro {

struct FrameImage;

struct RuntimeOptions {
  bool readback = true;     // read each frame's first view back into the FrameImage resource
  int width_override = 0;   // > 0: replaces the scene's output size (per eye)
  int height_override = 0;
  StereoMode stereo_mode = StereoMode::mono;
  std::optional<BillboardAlignment> alignment;  // replaces the scene's choice
  std::optional<ParticleShape> particles;       // replaces the scene's choice
  std::optional<float> layer_scale;             // replaces the scene's choice
  std::optional<ParticleShading> shading;       // replaces the scene's choice
  float frame_scale = 1.0f;                     // views at this fraction, output upscaled
  std::optional<float> interocular;
  std::optional<float> zero_parallax_distance;
  std::optional<bool> swap_eyes;  // replaces the scene's eye order
  // Finish the GPU's work after every system, so each system's timing includes the GPU work it
  // issued (profiling; it removes CPU/GPU overlap, so frames get slower).
  bool sync_timing = false;
  // Profiling session: every step() records one span per system (CPU time, from the schedule)
  // and one per GPU pass (timer queries: each render, composite and output system, and the
  // layers inside billboard_render with the fragments they drew), read one frame late.
  bool profile = false;
  // Makes the OpenGL context the runtime renders with current. Empty: the shared headless EGL
  // context. The viewer (pyro view) passes its window's context, so that the output target
  // lives where the window can blit it.
  std::function<void()> make_context_current;
};

// The process-wide headless context (made on first use).
gpu::HeadlessContext& shared_headless_context();

class SceneRuntime {
 public:
  explicit SceneRuntime(const SceneDescription& scene, const RuntimeOptions& options = {});

  // Runs every system once for the current frame, then advances the clock.
  void step();
  // Runs only the spawn and simulate phases for the current frame (no sorting, rendering or
  // output), then advances the clock: the particle state afterwards is the one step() leaves.
  // `pyro render --frames A:B` uses it to reach frame A without drawing the frames before it.
  void simulate_step();
  // Draws the last frame's state again (sort, camera, render, composite and output phases, at
  // the last frame's time) without running spawn or simulate and without advancing the clock:
  // the viewer paused, with the camera moving. After step(), redraw() gives the same image.
  void redraw();
  uint64_t frame() const;

  // The profiling session so far (options.profile): a "frame" span per step() on the CPU track
  // with the systems' spans inside it, and the GPU passes on the GPU track. Waits for the GPU to
  // finish the last frame's passes. Empty when not profiling.
  const std::vector<TraceSpan>& trace();

  ecs::World& world() { return world_; }
  const ecs::Schedule& schedule() const { return schedule_; }
  const SceneDescription& scene() const { return scene_; }
  const RenderSettings& settings();
  // The last frame's first view, linear (requires options.readback).
  const FrameImage& image();
  // The last composed frame as shown (upscaled when the frame scale is below 1), RGBA8 sRGB.
  struct OutputImage {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
  };
  OutputImage read_output();
  // The target holding the last composed frame as shown (the upscaled one when the frame scale
  // is below 1): GL_SRGB8_ALPHA8, in the runtime's context.
  const gpu::RenderTarget& output_target();
  // Writes the last composed frame as sRGB PNG: `stem`.png, or `stem`_left.png and
  // `stem`_right.png in left-right mode. Returns the paths written.
  std::vector<std::string> write_png(const std::string& stem);

 private:
  SceneDescription scene_;
  ecs::World world_;
  ecs::Schedule schedule_;
  // Profiling (options.profile): time 0 of the trace, the GPU timer, the spans so far.
  std::chrono::steady_clock::time_point profile_origin_{};
  std::unique_ptr<gpu::GpuPassTimer> gpu_timer_;
  std::vector<TraceSpan> trace_;
  bool profiling_ = false;
  void record_cpu_spans();
  void collect_gpu_spans();
  std::function<void()> make_current_;
};

}  // namespace pyro
