#include "systems/runtime/scene_runtime/scene_runtime.h"

#include <epoxy/gl.h>

#include <stdexcept>

#include "components/frame_clock.h"
#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "systems/output/linear_readback.h"
#include "systems/output/transparent_frame.h"
#include "systems/runtime/scene_runtime/build_world.h"
#include "systems/runtime/scene_runtime/load_scene_assets.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"
#include "systems/runtime/scene_runtime/standard_schedule.h"

namespace pyro {

gpu::HeadlessContext& shared_headless_context() {
  static gpu::HeadlessContext context;
  return context;
}

namespace {

std::function<void()> context_maker(const RuntimeOptions& options) {
  if (options.make_context_current) return options.make_context_current;
  return [] { shared_headless_context().make_current(); };
}

int driver_max_texture(const RuntimeOptions& options) {
  context_maker(options)();
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return size;
}

// The world, built in the runtime's context. Every pass works in linear light: writes to sRGB
// targets are encoded and reads decoded (it changes nothing for float targets).
ecs::World world_in_context(const std::function<void()>& make_current, const ResolvedScene& resolved,
                            SceneAssets assets) {
  make_current();
  glEnable(GL_FRAMEBUFFER_SRGB);
  return build_world(resolved, std::move(assets));
}

}  // namespace

SceneRuntime::SceneRuntime(const SceneDescription& scene, const RuntimeOptions& options)
    : SceneRuntime(resolve_scene(scene, options, driver_max_texture(options)), options) {}

SceneRuntime::SceneRuntime(const ResolvedScene& resolved, const RuntimeOptions& options)
    : SceneRuntime(resolved, load_scene_assets(resolved, options.on_note, options.asset_cache),
                   options) {}

SceneRuntime::SceneRuntime(const ResolvedScene& resolved, SceneAssets assets,
                           const RuntimeOptions& options)
    : make_current_(context_maker(options)),
      resolved_(resolved),
      notes_(assets.notes),
      world_(world_in_context(make_current_, resolved, std::move(assets))),
      schedule_(standard_schedule(options)),
      sequencer_(resolved.substeps, resolved.settings.motion_blur > 0.0f) {
  if (options.profile) profiler_ = std::make_unique<RuntimeProfiler>();
  make_current_();
  schedule_.setup(world_);  // renderers, scratch and outputs, in the runtime's context
}

void SceneRuntime::step() {
  make_current_();
  if (!profiler_) {
    schedule_.run_frame(world_);
  } else {
    const RuntimeProfiler::FrameScope active = profiler_->begin_frame(frame());
    schedule_.run_frame(world_);
    profiler_->end_frame(schedule_.stats(), frame());
  }
  world_.resource<FrameClock>().frame += 1;
}

std::vector<TraceSpan> SceneRuntime::take_trace() {
  if (!profiler_) return {};
  make_current_();
  return profiler_->take_spans();
}

const std::vector<TraceSpan>& SceneRuntime::trace() {
  static const std::vector<TraceSpan> none;
  if (!profiler_) return none;
  make_current_();
  return profiler_->trace();
}

void SceneRuntime::redraw() {
  make_current_();
  // The last frame drawn was the one before the clock's (step() advances it after drawing):
  // draw at that frame again, so time-dependent shading (heat shimmer) stays put.
  FrameClock& clock = world_.resource<FrameClock>();
  const uint64_t next = clock.frame;
  if (next > 0) clock.frame = next - 1;
  schedule_.run_phases(world_, ecs::Phase::light, ecs::Phase::output);
  world_.resource<FrameClock>().frame = next;
}

void SceneRuntime::simulate_step() {
  schedule_.run_phases_through(world_, ecs::Phase::simulate);
  world_.resource<FrameClock>().frame += 1;
}

uint64_t SceneRuntime::frame() const {
  return const_cast<ecs::World&>(world_).resource<FrameClock>().frame;
}

const FrameImage& SceneRuntime::image() {
  const FrameImage* img = world_.try_resource<FrameImage>();
  if (!img || !img->valid) throw std::logic_error("no frame has been read back yet");
  return *img;
}

const RenderSettings& SceneRuntime::settings() { return world_.resource<RenderSettings>(); }

const gpu::RenderTarget& SceneRuntime::output_target() {
  const GpuFrame& frame = world_.resource<GpuFrame>();
  return frame.display ? *frame.display : *frame.output;
}

ShownImage SceneRuntime::read_output() {
  make_current_();
  const gpu::RenderTarget& out = output_target();
  return {out.width(), out.height(), out.read_rgba8()};
}

std::vector<LinearView> SceneRuntime::read_linear(bool with_depth) {
  make_current_();
  return read_linear_views(world_, with_depth);
}

std::optional<FrameBackground> SceneRuntime::transparent_background() {
  make_current_();
  return held_background(world_);
}

bool SceneRuntime::shown_side_by_side() {
  return settings().stereo_mode == StereoMode::left_right;
}

}  // namespace pyro
