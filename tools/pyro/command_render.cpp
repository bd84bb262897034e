// pyro render SCENE --out DIR [--width W] [--height H] [--frames N | --frames A:B] [--json]
//                  [--format png|exr [--depth]] [--video FILE [--video-quality Q]]
//                  [--wait] [--overwrite | --resume]
//
// Each frame drawn is read back once and handed to the output sinks the options ask for
// (systems/output/frame_output.h): PNG or EXR frames in DIR, and a video.
// DIR has one writer at a time and a manifest keyed on the run's identity (its content:
// systems/runtime/scene_runtime/run_identity.h; engine/io/output_folder.h). Frames are rendered into a
// temporary folder inside DIR and moved into place only when every frame has been written: a
// failure (or a refusal) leaves DIR as it was. With --resume, the frames a killed run of the same
// identity finished, and those DIR already holds, are kept and only the others drawn (still
// simulated from frame 0: the same bytes as an uninterrupted run); frames of another identity
// (an edited scene or asset) are drawn again and counted. Which
// steps make which frames (substeps, the motion-blur prefix, ranges) is the runtime's
// FrameSequencer.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/same_file.h"
#include "engine/core/trace_events.h"
#include "engine/core/user_error.h"
#include "engine/io/output_folder.h"
#include "engine/io/text_file.h"
#include "engine/io/video_file.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/output/frame_output.h"
#include "systems/output/exr_sink.h"
#include "systems/output/png_sink.h"
#include "systems/output/video_sink.h"
#include "systems/runtime/quality_picker/quality_picker.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/frame_range.h"
#include "systems/runtime/scene_runtime/particle_counts.h"
#include "systems/runtime/scene_runtime/run_identity.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "systems/runtime/scene_runtime/render_identity.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/scene_inputs.h"
#include "tools/pyro/stdout_text.h"
#include "tools/pyro/trace_path.h"

namespace pyro::cli {

namespace {

struct RenderArgs {
  std::string scene;
  std::string out;
  int width = 0, height = 0;
  std::string frames = "1";
  bool json = false;
  std::string trace;  // --trace FILE: Chrome trace-event JSON of the run
  std::string format = "png";  // --format png|exr
  bool depth = false;          // --depth: EXR frames with a view-depth channel Z
  std::string video;           // --video FILE: the frames encoded as they are rendered
  int video_quality = VideoWriter::default_quality;
  OutputFolderOptions folder;  // --wait, --overwrite, --resume
  RuntimeOptions runtime;
};

nlohmann::json render_summary(const RenderArgs& a, SceneRuntime& runtime, const FrameRange& range,
                              const nlohmann::json& files, double seconds) {
  const RenderSettings& rs = runtime.settings();
  nlohmann::json systems = nlohmann::json::array();
  for (const auto& s : runtime.schedule().stats())
    systems.push_back({{"name", s.name}, {"phase", ecs::phase_name(s.phase)}, {"mean_ms", s.mean_ms()}});
  nlohmann::json summary = {
      {"scene", runtime.scene().file},
      {"name", runtime.scene().name},
      {"out", a.out},
      {"frames", range.count()},
      {"first_frame", range.first},
      {"last_frame", range.last},
      {"width", rs.width},
      {"height", rs.height},
      {"stereo", name_of(rs.stereo_mode)},
      {"billboards", name_of(rs.alignment)},
      {"layer_scale", rs.layer_scale},
      {"particles", live_particles(runtime.world())},
      {"drawn_particles", drawn_particles(runtime.world())},
      {"files", files},
      {"seconds", seconds},
      {"ms_per_frame", seconds * 1000.0 / range.count()},
      {"systems", systems},
      {"renderer", shared_headless_context().description()}};
  if (!a.trace.empty()) summary["trace"] = a.trace;
  return summary;
}

std::string describe_difference(const std::string& before, const std::string& now) {
  return identity_difference(nlohmann::json::parse(before), nlohmann::json::parse(now));
}

struct DrawnFrames {
  nlohmann::json files = nlohmann::json::array();  // every file of the range, under --out
  int drawn = 0;                                   // frames drawn by this run (the rest kept)
};

void say_what_the_folder_held(const OutputFolder& folder, const RenderArgs& a) {
  if (folder.discarded_files() > 0)
    print_note("removed " + std::to_string(folder.discarded_files()) + " finished frame file(s) a "
               "killed run of this render had left in " + a.out + " (--resume keeps them)");
  else if (folder.removed_leftovers() > 0)
    print_note("removed " + std::to_string(folder.removed_leftovers()) +
               " leftover(s) of killed runs from " + a.out);
  if (folder.replaced_files() > 0)
    print_note("replacing " +
               std::to_string(folder.replaced_files()) + " file(s) of " + a.out + ": it " +
               folder.replaced_because());
}

// Draws the frames of `range` that the output folder does not already hold finished (all of them
// unless --resume) and hands each to the sinks of `output`.
DrawnFrames draw_into(SceneRuntime& runtime, const OutputFolder& folder, FrameOutput& output,
                      const FrameRange& range, const RenderArgs& a) {
  say_what_the_folder_held(folder, a);
  DrawnFrames result;
  for (int f = range.first; f <= range.last; ++f)
    for (const std::string& name : output.files(f))
      result.files.push_back((std::filesystem::path(a.out) / name).string());
  const std::vector<int> to_draw = output.frames_to_draw(range.first, range.last);
  if (a.folder.resume)
    print_note("resuming: " + std::to_string(range.count() - static_cast<int>(to_draw.size())) +
               " of " + std::to_string(range.count()) + " frame(s) already finished");
  Progress progress("render " + runtime.scene().name, to_draw.size());
  for (size_t i = 0; i < to_draw.size(); ++i) {
    runtime.draw_frame(to_draw[i]);
    output.write(to_draw[i], runtime);
    progress.update(i + 1);
  }
  progress.finish();
  result.drawn = static_cast<int>(to_draw.size());
  return result;
}

// The sinks the arguments ask for, in the folder's common frame.
FrameOutput frame_output(OutputFolder& folder, SceneRuntime& runtime, const RenderArgs& a) {
  FrameOutput output(folder, a.folder.resume);
  if (a.format == "exr")
    output.add(std::make_unique<ExrSink>(runtime.settings().stereo_mode != StereoMode::mono, a.depth));
  else
    output.add(std::make_unique<PngSink>(runtime.shown_side_by_side()));
  if (!a.video.empty())
    output.add(std::make_unique<VideoSink>(a.video, runtime.scene().frames_per_second,
                                           a.video_quality));
  return output;
}

// Everything the user can get wrong that needs no reading of the scene.
void check_render_arguments(const RenderArgs& a) {
  std::error_code ec;
  if (std::filesystem::exists(a.out, ec) && !std::filesystem::is_directory(a.out, ec))
    throw UserError(a.out, "--out", "expected a folder for the frames, found a file");
  if (!a.trace.empty()) check_trace_path(a.trace, "--trace");
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

// The pick recorded with the folder's run (every range of a run draws with the same pick, cache
// or no cache); none when the scene sets no target, the folder records none, or a damaged one
// (noted; the front door then picks again).
std::optional<QualityPick> recorded_quality(const SceneDescription& scene,
                                            const OutputFolder& folder, const std::string& out) {
  if (!scene.quality.given()) return std::nullopt;
  const std::string recorded = folder.recorded("quality");
  if (recorded.empty()) return std::nullopt;
  try {
    QualityPick pick = quality_pick_from_json(nlohmann::json::parse(recorded), scene);
    pick.from_cache = true;
    pick.cache_file = (std::filesystem::path(out) / kOutputManifestName).string();
    return pick;
  } catch (const std::exception& e) {
    print_note(std::string("quality: the pick recorded with the folder's run is damaged (") +
               e.what() + "); picking again");
    return std::nullopt;
  }
}

void print_render_result(const RenderArgs& a, const SceneDescription& scene, const FrameRange& range,
                         const DrawnFrames& drawn, const nlohmann::json& summary, double seconds) {
  if (a.json) {
    write_stdout(summary.dump() + "\n");
    return;
  }
  const std::string kept =
      drawn.drawn < range.count()
          ? ", " + std::to_string(range.count() - drawn.drawn) + " kept from an earlier run"
          : "";
  // (The particle count is the last drawn frame's: none when every frame was kept.)
  const std::string particles =
      drawn.drawn > 0 ? ", " + std::to_string(summary["particles"].get<size_t>()) + " particles" : "";
  char line[1024];
  std::snprintf(line, sizeof line, "rendered %d frame(s) of %s (%dx%d %s%s%s) into %s in %.2f s\n",
                drawn.drawn, scene.file.c_str(), summary["width"].get<int>(),
                summary["height"].get<int>(), summary["stereo"].get<std::string>().c_str(),
                particles.c_str(), kept.c_str(), a.out.c_str(), seconds);
  write_stdout(line);
}

void run_render(const RenderArgs& a) {
  // Everything the user can get wrong is checked before anything is written.
  const FrameRange range = parse_frame_range(a.frames, "--frames");
  check_render_arguments(a);
  const SceneDescription scene = load_scene(a.scene);
  if (!a.trace.empty()) {
    refuse_output_over_inputs(a.trace, "--trace", scene_inputs(a.scene, scene));
    refuse_output_inside(a.trace, "--trace", a.out, "--out's frames and manifest");
  }
  if (!a.video.empty()) {
    refuse_output_over_inputs(a.video, "--video", scene_inputs(a.scene, scene));
    refuse_output_inside(a.video, "--video", a.out, "--out's frames and manifest");
  }

  RuntimeOptions options = a.runtime;
  options.readback = false;
  options.width_override = a.width;
  options.height_override = a.height;
  options.profile = !a.trace.empty();
  const auto t0 = std::chrono::steady_clock::now();
  // The default flipbook baked (a note first) before the identity digests its folder.
  prepare_scene_run(scene, options);
  OutputFolder folder(a.out, render_identity_json(scene, options, a.scene, a.depth).dump(), describe_difference, a.folder);
  // A quality target (scene key quality.max_rmse) picks the layer scale, footprint size and time
  // step once for the run, recorded with it before anything is drawn.
  OpenSceneOptions open;
  open.runtime = options;
  open.description = scene;
  open.quality = recorded_quality(scene, folder, a.out);
  open.on_note = print_note;
  open.on_pick = [&folder](const std::optional<QualityPick>& pick) {
    folder.begin(nlohmann::json{{"quality", pick ? pick->to_json() : nlohmann::json()}}.dump());
  };
  const OpenedScene opened = open_scene(a.scene, open);  // refuses a scene over its budget
  SceneRuntime& runtime = *opened.runtime;
  const std::optional<QualityPick>& quality = opened.quality;
  FrameOutput output = frame_output(folder, runtime, a);
  const DrawnFrames drawn = draw_into(runtime, folder, output, range, a);
  output.commit();
  if (!a.trace.empty())
    write_text_file(a.trace, chrome_trace_json(runtime.trace(), "pyro render " + scene.file));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  nlohmann::json summary = render_summary(a, runtime, range, drawn.files, seconds);
  summary["drawn_frames"] = drawn.drawn;
  summary["kept_frames"] = range.count() - drawn.drawn;
  summary["replaced_files"] = folder.replaced_files();
  if (quality) summary["quality"] = quality_pick_summary(*quality);
  print_render_result(a, scene, range, drawn, summary, seconds);
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to PNG or EXR frames (and a video)");
  cmd->add_option("scene", args->scene, "Scene file (JSON), e.g. content/scenes/fog.json; - reads it from standard input")->required();
  cmd->add_option("--out", args->out, "Folder for frame_0000.png (or .exr), frame_0001.png, ...")->required();
  cmd->add_option("--width", args->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", args->frames,
                  "N: frames 0..N-1; A:B: frames A..B inclusive (simulated from frame 0, only A..B "
                  "written, named frame_A.png ...)");
  cmd->add_option("--format", args->format,
                  "Frame files: png (8-bit sRGB, as shown) or exr (linear half-float RGBA, as "
                  "the framebuffer holds it; _left/_right per eye in stereo)")
      ->check(CLI::IsMember({"png", "exr"}));
  cmd->add_flag("--depth", args->depth,
                "With --format exr: a float channel Z, the view depth of the opaque geometry "
                "(+infinity where none)");
  cmd->add_option("--video", args->video,
                  "Also encode the frames as shown into FILE (.mp4 H.264, .webm VP9 or .gif) at "
                  "the scene's fps; written into place only when the render succeeds");
  cmd->add_option("--video-quality", args->video_quality,
                  "0..100 (default 75): the codec's constant-rate factor, 100 the best")
      ->check(CLI::Range(0, 100));
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  cmd->add_option("--trace", args->trace,
                  "Write a Chrome trace-event JSON file (opens in Perfetto): one span per system "
                  "and GPU pass per frame");
  cmd->add_flag("--wait", args->folder.wait,
                "Wait for another run writing into --out to finish (default: refuse)");
  cmd->add_flag("--overwrite", args->folder.overwrite,
                "Replace --out's frames of another run (another scene, asset or settings)");
  cmd->add_flag("--resume", args->folder.resume,
                "Finish a killed run: keep the frames it (and --out) already hold for this run "
                "(same scene, assets, settings and engine), draw the others");
  add_render_options(cmd, args->runtime);
  cmd->callback([args] { run_render(*args); });
}

}  // namespace pyro::cli
