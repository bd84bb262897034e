#include "tools/analyze/billboard_modes.h"

#include <cstddef>
#include <memory>

#include "components/frame_image.h"
#include "engine/core/format_text.h"
#include "engine/math/image_error.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/bench/frame_timing.h"

namespace pyro {

namespace {

struct ModeRun {
  FrameImage image;
  double ms_per_frame;
};

// `progress` advances by frames + 2 (the warm-up, the timed frames, the imaged frame) from `done`.
ModeRun run_mode(const SceneDescription& scene, const BillboardModesOptions& a,
                 BillboardAlignment alignment, ProgressTask& progress, size_t done) {
  RuntimeOptions o;
  o.stereo_mode = StereoMode::left_right;
  o.alignment = alignment;
  o.width_override = a.width;
  o.height_override = a.height;
  // Timed without readback; the image comes from a second runtime at the same frame.
  const double ms = median_ms_per_frame(scene, o, a.frames);
  done += size_t(a.frames) + 1;
  progress.update(done);
  o.readback = true;
  // The modes are compared at the scene's written settings (a quality pick's layer scale would
  // blur the difference measured); median_ms_per_frame times them alike.
  const std::unique_ptr<SceneRuntime> imaged = open_runtime(scene, o);  // the written settings
  imaged->step();
  progress.update(++done);
  return {imaged->image(), ms};
}

}  // namespace

AnalysisReport analyze_billboard_modes(const BillboardModesOptions& a) {
  const SceneDescription scene = load_scene(a.scene);
  prepare_scene_run(scene);  // before the timed runtimes (tools/bench/frame_timing.h) open it
  const size_t per_mode = size_t(a.frames) + 2;
  ProgressTask progress(a.progress, "analyze billboard-modes", 2 * per_mode);
  progress.stage(0, std::string(name_of(BillboardAlignment::viewplane)));
  const ModeRun plane = run_mode(scene, a, BillboardAlignment::viewplane, progress, 0);
  progress.stage(per_mode, std::string(name_of(BillboardAlignment::viewpoint)));
  const ModeRun point = run_mode(scene, a, BillboardAlignment::viewpoint, progress, per_mode);
  progress.finish();
  AnalysisReport r;
  r.json = {
      {"scene", scene.file},
      {"width", plane.image.width},
      {"height", plane.image.height},
      {"eyes",
       {{{"eye", "left"}, {"rmse", rgba_rmse(plane.image.rgba, point.image.rgba)}},
        {{"eye", "right"}, {"rmse", rgba_rmse(plane.image.right_rgba, point.image.right_rgba)}}}},
      {"viewplane_ms_per_stereo_frame", plane.ms_per_frame},
      {"viewpoint_ms_per_stereo_frame", point.ms_per_frame}};
  r.text += format_text("%s: viewplane vs viewpoint billboards, %dx%d per eye\n",
                        scene.file.c_str(), plane.image.width, plane.image.height);
  for (const auto& e : r.json["eyes"])
    r.text += format_text("  %-5s eye RMSE %.5f\n", e["eye"].get<std::string>().c_str(),
                          e["rmse"].get<double>());
  r.text += format_text("  viewplane %.2f ms, viewpoint %.2f ms per stereo frame\n",
                        plane.ms_per_frame, point.ms_per_frame);
  return r;
}

}  // namespace pyro
