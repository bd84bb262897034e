#include "tools/bench/frame_timing.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace pyro {

double median_ms_per_frame(const SceneDescription& scene, RuntimeOptions options, int frames) {
  options.readback = false;
  // behind the front door: times the settings its caller sets (a chart's or benchmark's)
  SceneRuntime timed(scene, options);
  timed.step();
  glFinish();
  std::vector<double> ms;
  for (int f = 0; f < std::max(1, frames); ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    timed.step();
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace pyro
