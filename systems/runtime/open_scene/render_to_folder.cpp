#include "systems/runtime/open_scene/render_to_folder.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/trace_events.h"
#include "engine/io/text_file.h"
#include "systems/output/exr_sink.h"
#include "systems/output/frame_output.h"
#include "systems/output/png_sink.h"
#include "systems/output/video_sink.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/quality_picker/quality_picker.h"
#include "systems/runtime/scene_runtime/particle_counts.h"
#include "systems/runtime/scene_runtime/render_identity.h"
#include "systems/runtime/scene_runtime/run_identity.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

nlohmann::json folder_render_summary(const FolderRenderRequest& a, SceneRuntime& runtime,
                                     const FrameRange& range, const nlohmann::json& files,
                                     double seconds) {
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

std::string describe_identity_difference(const std::string& before, const std::string& now) {
  return identity_difference(nlohmann::json::parse(before), nlohmann::json::parse(now));
}

struct DrawnFrames {
  nlohmann::json files = nlohmann::json::array();  // every file of the range, in the folder
  int drawn = 0;                                   // frames drawn by this run (the rest kept)
};

void say_what_the_folder_held(const OutputFolder& folder, const FolderRenderRequest& a,
                              const NoteSink& note) {
  if (folder.discarded_files() > 0)
    note("removed " + std::to_string(folder.discarded_files()) + " finished frame file(s) a "
         "killed run of this render had left in " + a.out + " (--resume keeps them)");
  else if (folder.removed_leftovers() > 0)
    note("removed " + std::to_string(folder.removed_leftovers()) +
         " leftover(s) of killed runs from " + a.out);
  if (!folder.damaged_files().empty()) {
    std::string names;
    for (const std::string& name : folder.damaged_files()) names += (names.empty() ? "" : ", ") + name;
    note(std::to_string(folder.damaged_files().size()) + " frame file(s) of " + a.out +
         " are damaged (their bytes differ from the SHA-256 its manifest records): " +
         names.substr(0, 400) + "; none is kept (drawn again when in the range, else removed)");
  }
  if (folder.replaced_files() > 0)
    note("replacing " + std::to_string(folder.replaced_files()) + " file(s) of " + a.out +
         ": it " + folder.replaced_because());
}

// Draws the frames of `range` that the output folder does not already hold finished (all of them
// unless resuming) and hands each to the sinks of `output`.
DrawnFrames draw_into(SceneRuntime& runtime, const OutputFolder& folder, FrameOutput& output,
                      const FrameRange& range, const FolderRenderRequest& a, const NoteSink& note,
                      ProgressSink* progress_sink) {
  say_what_the_folder_held(folder, a, note);
  DrawnFrames result;
  for (int f = range.first; f <= range.last; ++f)
    for (const std::string& name : output.files(f))
      result.files.push_back((std::filesystem::path(a.out) / name).string());
  const std::vector<int> to_draw = output.frames_to_draw(range.first, range.last);
  if (a.folder.resume)
    note("resuming: " + std::to_string(range.count() - static_cast<int>(to_draw.size())) +
         " of " + std::to_string(range.count()) + " frame(s) already finished");
  ProgressTask progress(progress_sink, "render " + runtime.scene().name, to_draw.size());
  for (size_t i = 0; i < to_draw.size(); ++i) {
    runtime.draw_frame(to_draw[i]);
    output.write(to_draw[i], runtime);
    progress.update(i + 1);
  }
  progress.finish();
  result.drawn = static_cast<int>(to_draw.size());
  return result;
}

// The sinks the request asks for, in the folder's common frame.
FrameOutput frame_output(OutputFolder& folder, SceneRuntime& runtime, const FolderRenderRequest& a) {
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

// The pick recorded with the folder's run (every range of a run draws with the same pick, cache
// or no cache); none when the scene sets no target, the folder records none, or a damaged one
// (noted; the front door then picks again).
std::optional<QualityPick> recorded_quality(const SceneDescription& scene,
                                            const OutputFolder& folder, const std::string& out,
                                            const NoteSink& note) {
  if (!scene.quality.given()) return std::nullopt;
  const std::string recorded = folder.recorded("quality");
  if (recorded.empty()) return std::nullopt;
  try {
    QualityPick pick = quality_pick_from_json(nlohmann::json::parse(recorded), scene);
    pick.from_cache = true;
    pick.cache_file = (std::filesystem::path(out) / kOutputManifestName).string();
    return pick;
  } catch (const std::exception& e) {
    note(std::string("quality: the pick recorded with the folder's run is damaged (") + e.what() +
         "); picking again");
    return std::nullopt;
  }
}

}  // namespace

FolderRender render_to_folder(const FolderRenderRequest& a, const SceneDescription& scene,
                              const FrameRange& range, const NoteSink& note,
                              ProgressSink* progress) {
  RuntimeOptions options = a.runtime;
  options.readback = false;
  options.width_override = a.width;
  options.height_override = a.height;
  options.profile = !a.trace.empty();
  const auto t0 = std::chrono::steady_clock::now();
  // The default flipbook baked (a note first) before the identity digests its folder.
  prepare_scene_run(scene, options);
  nlohmann::json identity = render_identity_json(scene, options, a.scene_path, a.depth);
  if (nlohmann::json source = scene_source(a.scene_path); !source.is_null()) identity["source"] = source;
  OutputFolder folder(a.out, identity.dump(), describe_identity_difference, a.folder);
  // A quality target picks the layer scale, footprint size and time step once for the run,
  // recorded with it before anything is drawn.
  OpenSceneOptions open;
  open.runtime = options;
  open.description = scene;
  open.quality = recorded_quality(scene, folder, a.out, note);
  open.on_note = note;
  open.on_pick = [&folder](const std::optional<QualityPick>& pick) {
    folder.begin(nlohmann::json{{"quality", pick ? pick->to_json() : nlohmann::json()}}.dump());
  };
  const OpenedScene opened = open_scene(a.scene_path, open);  // refuses a scene over its budget
  SceneRuntime& runtime = *opened.runtime;
  FrameOutput output = frame_output(folder, runtime, a);
  const DrawnFrames drawn = draw_into(runtime, folder, output, range, a, note, progress);
  output.commit();
  if (!a.trace.empty())
    write_text_file(a.trace, chrome_trace_json(runtime.trace(), "pyro render " + scene.file));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  FolderRender result{folder_render_summary(a, runtime, range, drawn.files, seconds), drawn.drawn};
  result.summary["drawn_frames"] = drawn.drawn;
  result.summary["kept_frames"] = range.count() - drawn.drawn;
  result.summary["replaced_files"] = folder.replaced_files();
  if (opened.quality) result.summary["quality"] = quality_pick_summary(*opened.quality);
  return result;
}

}  // namespace pyro
