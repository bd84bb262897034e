#include "tools/bench/bench_render.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "components/draw_list.h"
#include "components/gpu_frame.h"
#include "components/view.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/billboard_render/billboard_renderer.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "engine/core/progress_sink.h"

namespace pyro {

namespace {

double upper_median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  if (v.empty()) return 0.0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5));
  return v[k];
}

using Clock = std::chrono::steady_clock;

}  // namespace

nlohmann::json bench_render(const RenderBenchOptions& o) {
  OpenSceneOptions open;  // the scene as every command opens it: its quality pick applied
  open.runtime.readback = false;
  open.runtime.width_override = o.width;
  open.runtime.height_override = o.height;
  const OpenedScene opened = open_scene(o.scene, open);
  const SceneDescription& scene = opened.description;
  SceneRuntime& runtime = *opened.runtime;
  ProgressTask progress(o.progress, "bench render", static_cast<size_t>(o.frames + 2 * o.pass_repeats));

  for (int i = 0; i < 3; ++i) runtime.step();  // warm up: programs, buffers, caches
  glFinish();
  std::vector<double> frame_ms;
  for (int f = 0; f < o.frames; ++f) {
    const auto t0 = Clock::now();
    runtime.step();
    glFinish();
    frame_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    progress.update(static_cast<size_t>(f + 1));
  }

  // The particle pass alone, over the last frame's opaque depth buffer.
  ecs::World& world = runtime.world();
  const EyeDrawLists& lists = world.resource<EyeDrawLists>();
  const DrawList& list = lists.eyes.at(0);
  const CameraFrame& frame = world.resource<View>().eyes.at(0);
  const gpu::RenderTarget& target = *world.resource<GpuFrame>().eyes.at(0).scene;
  BillboardRenderer& renderer = world.resource<BillboardRenderer>();
  gpu::Query query = gpu::make_query(GL_SAMPLES_PASSED);
  auto timed_pass = [&](BillboardShading shading, GLuint64& fragments) {
    glFinish();
    const auto t0 = Clock::now();
    glBeginQuery(GL_SAMPLES_PASSED, query.get());
    renderer.draw(list, lists.pools, frame, target, BillboardAlignment::viewplane, shading);
    glEndQuery(GL_SAMPLES_PASSED);
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    glGetQueryObjectui64v(query.get(), GL_QUERY_RESULT, &fragments);
    return ms;
  };
  std::vector<double> kernel_ms, trivial_ms;
  GLuint64 kernel_fragments = 0, trivial_fragments = 0;
  for (int r = 0; r < o.pass_repeats; ++r) {
    kernel_ms.push_back(timed_pass(BillboardShading::kernel, kernel_fragments));
    trivial_ms.push_back(timed_pass(BillboardShading::trivial, trivial_fragments));
    progress.update(static_cast<size_t>(o.frames + 2 * (r + 1)));
  }
  progress.finish();

  const double frame_med = upper_median(frame_ms);
  const double kernel_med = upper_median(kernel_ms), trivial_med = upper_median(trivial_ms);
  const double fragments = static_cast<double>(kernel_fragments);
  return {{"scene", scene.file},
          {"width", target.width()},
          {"height", target.height()},
          {"particles", list.size()},
          {"frames", o.frames},
          {"ms_per_frame", frame_med},
          {"ms_per_frame_p95", percentile(frame_ms, 0.95)},
          {"fps", frame_med > 0 ? 1000.0 / frame_med : 0.0},
          {"particle_pass_ms", kernel_med},
          {"trivial_pass_ms", trivial_med},
          {"fragments_per_frame", fragments},
          {"trivial_fragments_per_frame", static_cast<double>(trivial_fragments)},
          {"fragments_per_second", kernel_med > 0 ? fragments / (kernel_med / 1000.0) : 0.0},
          {"trivial_fragments_per_second",
           trivial_med > 0 ? static_cast<double>(trivial_fragments) / (trivial_med / 1000.0) : 0.0},
          {"efficiency", kernel_med > 0 ? trivial_med / kernel_med : 0.0},
          {"renderer", shared_headless_context().description()}};
}

}  // namespace pyro
