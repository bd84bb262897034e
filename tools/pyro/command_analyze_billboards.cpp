// pyro analyze billboard-modes SCENE [--width W] [--height H] [--frames N] [--json]
// The image difference between billboards facing the viewplane and facing the viewpoint
// (Johnson & McAllister 2005, section 3), per eye of a stereo pair, as RMSE of linear RGB,
// beside the time each mode takes per frame.
#include <cmath>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "components/frame_image.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/math/image_error.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"
#include "tools/bench/frame_timing.h"

namespace pyro::cli {

namespace {

struct Args {
  std::string scene;
  int width = 0, height = 0;
  int frames = 5;
  bool json = false;
};



struct ModeRun {
  FrameImage image;
  double ms_per_frame;
};

// `progress` advances by frames + 2 (the warm-up, the timed frames, the imaged frame) from `done`.
ModeRun run_mode(const SceneDescription& scene, const Args& a, BillboardAlignment alignment,
                 Progress& progress, size_t done) {
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
  SceneRuntime imaged(scene, o);  // behind the front door: the written settings, as above
  imaged.step();
  progress.update(++done);
  return {imaged.image(), ms};
}

void run(const Args& a) {
  const SceneDescription scene = load_scene(a.scene);
  const size_t per_mode = size_t(a.frames) + 2;
  Progress progress("analyze billboard-modes", 2 * per_mode);
  progress.stage(0, std::string(name_of(BillboardAlignment::viewplane)));
  const ModeRun plane = run_mode(scene, a, BillboardAlignment::viewplane, progress, 0);
  progress.stage(per_mode, std::string(name_of(BillboardAlignment::viewpoint)));
  const ModeRun point = run_mode(scene, a, BillboardAlignment::viewpoint, progress, per_mode);
  progress.finish();
  const nlohmann::json out = {
      {"scene", scene.file},
      {"width", plane.image.width},
      {"height", plane.image.height},
      {"eyes",
       {{{"eye", "left"}, {"rmse", rgba_rmse(plane.image.rgba, point.image.rgba)}},
        {{"eye", "right"}, {"rmse", rgba_rmse(plane.image.right_rgba, point.image.right_rgba)}}}},
      {"viewplane_ms_per_stereo_frame", plane.ms_per_frame},
      {"viewpoint_ms_per_stereo_frame", point.ms_per_frame}};
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf("%s: viewplane vs viewpoint billboards, %dx%d per eye\n", scene.file.c_str(),
              plane.image.width, plane.image.height);
  for (const auto& e : out["eyes"])
    std::printf("  %-5s eye RMSE %.5f\n", e["eye"].get<std::string>().c_str(), e["rmse"].get<double>());
  std::printf("  viewplane %.2f ms, viewpoint %.2f ms per stereo frame\n", plane.ms_per_frame,
              point.ms_per_frame);
}

}  // namespace

void add_billboard_mode_analysis(CLI::App& analyze) {
  auto a = std::make_shared<Args>();
  CLI::App* cmd = analyze.add_subcommand(
      "billboard-modes", "Image difference (RMSE per eye) and time: viewplane vs viewpoint billboards");
  cmd->add_option("scene", a->scene, "Scene file (JSON)")->required();
  cmd->add_option("--width", a->width, "Width per eye (default: the scene's)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", a->height, "Height (default: the scene's)")->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", a->frames, "Timed frames per mode")->check(CLI::Range(1, 10000));
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] { run(*a); });
}

}  // namespace pyro::cli
