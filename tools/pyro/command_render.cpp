// pyro render SCENE --out DIR [--width W] [--height H] [--frames N | --frames A:B] [--json]
//                  [--format png|exr [--depth]] [--background opaque|transparent]
//                  [--video FILE [--video-quality Q]]
//                  [--wait] [--overwrite | --resume]
//
// The run itself (output sinks, frame loop, the folder's identity and record) is
// render_to_folder (systems/runtime/open_scene/render_to_folder.h). Which steps make which frames
// (substeps, the motion-blur prefix, ranges) is the runtime's FrameSequencer.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/video_file.h"
#include "systems/runtime/open_scene/render_to_folder.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/frame_range.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct RenderArgs {
  FolderRenderRequest render;  // SCENE, --out, --width, --height, --trace, --format, --depth,
                               // --video, --video-quality, --wait, --overwrite, --resume
  std::string frames = "1";
  bool json = false;
};

// Everything the user can get wrong that needs no reading of the scene.
void check_render_arguments(const FolderRenderRequest& a) {
  if (a.depth && a.format != "exr")
    throw UserError("--depth", "", "--format exr: only EXR frames carry a depth channel");
  if (a.format == "exr" && a.runtime.frame_scale < 1.0f)
    throw UserError("--frame-scale", "", "1 with --format exr: EXR frames hold the views as "
                                         "rendered, and a frame scale below 1 renders them "
                                         "smaller, upscaling only the shown (PNG, video) frame");
  if (!a.video.empty()) check_video_path(a.video, "--video");
  if (a.folder.resume && a.folder.overwrite)
    throw UserError("--resume", "", "either --resume (keep this run's finished frames, draw the "
                                    "rest) or --overwrite (replace another run's), not both");
}

void print_render_result(const RenderArgs& a, const SceneDescription& scene, const FrameRange& range,
                         const FolderRender& result) {
  const nlohmann::json& summary = result.summary;
  if (a.json) {
    write_stdout(summary.dump() + "\n");
    return;
  }
  const std::string kept =
      result.drawn < range.count()
          ? ", " + std::to_string(range.count() - result.drawn) + " kept from an earlier run"
          : "";
  // (The particle count is the last drawn frame's: none when every frame was kept.)
  const std::string particles =
      result.drawn > 0 ? ", " + std::to_string(summary["particles"].get<size_t>()) + " particles" : "";
  char line[1024];
  std::snprintf(line, sizeof line, "rendered %d frame(s) of %s (%dx%d %s%s%s) into %s in %.2f s\n",
                result.drawn, scene.file.c_str(), summary["width"].get<int>(),
                summary["height"].get<int>(), summary["stereo"].get<std::string>().c_str(),
                particles.c_str(), kept.c_str(), a.render.out.c_str(),
                summary["seconds"].get<double>());
  write_stdout(line);
}

void run_render(const RenderArgs& args) {
  // Everything the user can get wrong is checked before anything is written.
  const FolderRenderRequest& a = args.render;
  const FrameRange range = parse_frame_range(args.frames, "--frames");
  check_render_arguments(a);
  const SceneDescription scene = load_scene(a.scene_path);
  OutputGate()
      .reads(scene_inputs(a.scene_path, scene))
      .writes({a.out, "--out", OutputShape::folder, render_output_kind(), a.folder.overwrite})
      .writes_file(a.trace, "--trace")
      .writes_file(a.video, "--video")
      .check();
  print_render_result(args, scene, range,
                      render_to_folder(a, scene, range, print_note, terminal_progress()));
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  FolderRenderRequest& r = args->render;
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to PNG or EXR frames (and a video)");
  cmd->add_option("scene", r.scene_path, "Scene file (JSON), e.g. content/scenes/fog.json; - reads it from standard input")->required();
  cmd->add_option("--out", r.out, "Folder for frame_0000.png (or .exr), frame_0001.png, ...")->required();
  cmd->add_option("--width", r.width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", r.height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", args->frames,
                  "N: frames 0..N-1; A:B: frames A..B inclusive (simulated from frame 0, only A..B "
                  "written, named frame_A.png ...)");
  cmd->add_option("--format", r.format,
                  "Frame files: png (8-bit sRGB, as shown) or exr (linear half-float RGBA, as "
                  "the framebuffer holds it; _left/_right per eye in stereo)")
      ->check(CLI::IsMember({"png", "exr"}));
  cmd->add_flag("--depth", r.depth,
                "With --format exr: a float channel Z, the view depth of the opaque geometry "
                "(+infinity where none)");
  cmd->add_option_function<std::string>(
         "--background",
         [&r](const std::string& v) {
           r.runtime.background = v == "transparent" ? OutputBackground::none : OutputBackground::opaque;
         },
         "opaque (the scene's background colour) or transparent (alpha the coverage of the media "
         "and meshes, over nothing; a video stays opaque) (default: the scene's output.background)")
      ->check(CLI::IsMember({"opaque", "transparent"}));
  cmd->add_option("--video", r.video,
                  "Also encode the frames as shown into FILE (.mp4 H.264, .webm VP9 or .gif) at "
                  "the scene's fps; written into place only when the render succeeds");
  cmd->add_option("--video-quality", r.video_quality,
                  "0..100 (default 75): the codec's constant-rate factor, 100 the best")
      ->check(CLI::Range(0, 100));
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  cmd->add_option("--trace", r.trace,
                  "Write a Chrome trace-event JSON file (opens in Perfetto): one span per system "
                  "and GPU pass per frame");
  cmd->add_flag("--wait", r.folder.wait,
                "Wait for another run writing into --out to finish (default: refuse)");
  cmd->add_flag("--overwrite", r.folder.overwrite,
                "Replace --out's frames of another run (another scene, asset or settings)");
  cmd->add_flag("--resume", r.folder.resume,
                "Finish a killed run: keep the frames it (and --out) already hold for this run "
                "(same scene, assets, settings and engine), draw the others");
  add_render_options(cmd, r.runtime);
  cmd->callback([args] { run_render(*args); });
}

}  // namespace pyro::cli
