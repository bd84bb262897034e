#pragma once
// A scene brought to life: the thin owner of the runtime's layers' results.
//   SceneDescription --resolve_scene(options)--> ResolvedScene      (resolve_scene.h)
//                    --load_scene_assets-->      SceneAssets        (load_scene_assets.h)
//                    --build_world-->            World              (build_world.h)
//                    + standard_schedule(options)                    (standard_schedule.h)
//                    --FrameSequencer-->         output frames      (frame_sequencer.h)
// Frame f shows the state after f simulation steps of dt = 1 / fps (after prewarm + f steps when
// the scene asks for a prewarm: those run when the world is built). Both eyes of a stereo pair
// render the same simulation state: simulation runs once per frame.
#include <cstdint>
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
#include "engine/gpu/render_target.h"
#include "systems/output/frame_source.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/frame_sequencer.h"
#include "systems/runtime/scene_runtime/resolved_scene.h"
#include "systems/runtime/scene_runtime/runtime_options.h"
#include "systems/runtime/scene_runtime/runtime_profiler.h"
#include "systems/runtime/scene_runtime/scene_assets.h"

namespace pyro {

struct FrameImage;

// The process-wide headless context (made on first use).
gpu::HeadlessContext& shared_headless_context();

class SceneRuntime : public FrameStepper, public FrameSource {
 public:
  // Every layer in turn: resolve (against the context's GL_MAX_TEXTURE_SIZE), load the assets
  // (notes to options.on_note), build the world and the standard schedule.
  explicit SceneRuntime(const SceneDescription& scene, const RuntimeOptions& options = {});
  // From the first two layers' results, made by the caller.
  SceneRuntime(const ResolvedScene& resolved, SceneAssets assets, const RuntimeOptions& options);

  // Runs every system once for the current frame, then advances the clock.
  void step() override;
  // Runs only the spawn and simulate phases for the current frame (no sorting, rendering or
  // output), then advances the clock: the particle state afterwards is the one step() leaves.
  void simulate_step() override;
  // Draws the last frame's state again (camera, sort, render, composite and output phases, at
  // the last frame's time) without running spawn or simulate and without advancing the clock:
  // the viewer paused, with the camera moving. After step(), redraw() gives the same image.
  void redraw();
  uint64_t frame() const override;

  // Output frames (frame_sequencer.h): brings the runtime to output frame f and draws it;
  // frames must ascend.
  void draw_frame(int f) { sequencer_.draw(*this, f); }
  void draw_frames(const FrameRange& range, const std::function<void(int)>& on_frame) {
    sequencer_.draw(*this, range, on_frame);
  }
  const FrameSequencer& sequencer() const { return sequencer_; }

  // The profiling run so far (options.profile): a "frame" span per step() on the CPU track
  // with the systems' spans inside it, and the GPU passes on the GPU track. Waits for the GPU to
  // finish the last frame's passes. Empty when not profiling.
  const std::vector<TraceSpan>& trace();
  // The spans since the last take (GPU passes up to the frame before), forgotten here: for a
  // long-running profiled session (the viewer's profiler panel). Empty when not profiling.
  std::vector<TraceSpan> take_trace();

  ecs::World& world() { return world_; }
  const ecs::Schedule& schedule() const { return schedule_; }
  // The scene as it runs (a quality pick applied: resolved().scene).
  const SceneDescription& scene() const { return resolved_.scene; }
  const ResolvedScene& resolved() const { return resolved_; }
  // The notes the assets' loading reported (also sent to options.on_note as they happened).
  const std::vector<std::string>& notes() const { return notes_; }
  const RenderSettings& settings();
  // The last frame's first view, linear (requires options.readback).
  const FrameImage& image();
  // The last composed frame as shown (upscaled when the frame scale is below 1), RGBA8 sRGB.
  ShownImage read_output();
  // The target holding the last composed frame as shown (the upscaled one when the frame scale
  // is below 1): GL_SRGB8_ALPHA8, in the runtime's context.
  const gpu::RenderTarget& output_target();

  // FrameSource, for the output phase's sinks (systems/output/frame_output.h).
  ShownImage read_shown() override { return read_output(); }
  std::vector<LinearView> read_linear(bool with_depth) override;
  bool shown_side_by_side() override;
  std::optional<FrameBackground> transparent_background() override;

 private:
  SceneRuntime(const ResolvedScene& resolved, const RuntimeOptions& options);

  std::function<void()> make_current_;
  ResolvedScene resolved_;
  std::vector<std::string> notes_;
  ecs::World world_;
  ecs::Schedule schedule_;
  FrameSequencer sequencer_;
  std::unique_ptr<RuntimeProfiler> profiler_;  // options.profile
};

}  // namespace pyro
