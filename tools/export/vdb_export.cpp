#include "tools/export/vdb_export.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/io/folder_replacement.h"
#include "engine/io/output_gate.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/frame_range.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "tools/export/column_error.h"
#include "tools/export/media_vdb.h"
#include "tools/export/vdb_sequence_naming.h"
#include "tools/export/voxel_size_choice.h"
#include "tools/export/world_media.h"

namespace pyro {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void check_numbers(const VdbExportOptions& o) {
  if (!(o.error > 0.0 && o.error <= 1.0))
    throw UserError("", "--error", format_text("a column opacity error in (0, 1], found %g", o.error));
  if (!(o.voxel_size >= 0.0 && std::isfinite(o.voxel_size) && o.voxel_size <= 1e6))
    throw UserError("", "--voxel-size", format_text("a voxel side in world units in (0, 1e6], found %g", o.voxel_size));
}

// Whether the samples' colours differ (by more than 1/1000 in any channel).
bool colours_vary(const std::vector<MediaSample>& samples) {
  for (const MediaSample& s : samples)
    for (int c = 0; c < 3; ++c)
      if (std::abs(s.color[c] - samples.front().color[c]) > 1e-3f) return true;
  return false;
}

bool has_fire(const std::vector<MediaSample>& samples) {
  return std::any_of(samples.begin(), samples.end(), [](const MediaSample& s) { return s.fire; });
}

// The run's state: the voxel size once chosen, the worst error, the per-frame rows.
struct ExportRun {
  ExportRun(const VdbExportOptions& options, std::string name_) : o(options), name(std::move(name_)) {}
  const VdbExportOptions& o;
  std::string name;
  double voxel = 0.0;        // the size now
  double first_voxel = 0.0;  // the size of the first frame with media
  int tries = 0;     // sizes measured in choosing
  bool chosen = false;
  nlohmann::json sizes = nlohmann::json::array();  // sizes chosen again at later frames
  double worst_opacity = 0.0, worst_depth = 0.0;
  uint64_t largest_grid = 0;
  nlohmann::json rows = nlohmann::json::array();
};

// The share of the target the chosen size aims at: headroom for later frames, whose media differ.
constexpr double kChoiceHeadroom = 0.75;

// The voxel size for the run, fixed at the first frame with media (a sequence's grids share one
// transform): the option's, else chosen; refused when the target needs a grid over the limit.
// A later frame that misses the target chooses again (`again`), and the frames from it on take
// the new size.
void fix_voxel_size(ExportRun& run, const std::vector<MediaSample>& samples, int frame, bool again = false) {
  if (run.chosen && !again) return;
  run.chosen = true;
  if (run.o.voxel_size > 0.0) {
    run.voxel = run.first_voxel = run.o.voxel_size;
    return;
  }
  const VoxelSizeChoice choice = choose_voxel_size(samples, kChoiceHeadroom * run.o.error, run.o.max_voxels);
  if (!choice.fits)
    throw UserError(run.o.scene, "--error",
                    format_text("an error target a grid of at most %llu voxels can meet: at the finest voxel size "
                                "that fits frame %d's media, %g, the column opacity error is %.4g, over the target %g; raise "
                                "--error or give --voxel-size",
                                (unsigned long long)run.o.max_voxels, frame, choice.voxel, choice.error.opacity_max,
                                run.o.error));
  run.tries += choice.tries;
  if (again) run.sizes.push_back({{"from_frame", frame}, {"voxel_size", choice.voxel}});
  run.voxel = choice.voxel;
  if (!again) run.first_voxel = choice.voxel;
}

void check_box(const ExportRun& run, const VoxelBox& box, int frame) {
  if (box.voxels() <= run.o.max_voxels) return;
  throw UserError(run.o.scene, "--voxel-size",
                  format_text("a grid of at most %llu voxels: frame %d's media at voxel size %g need %d x %d x %d; "
                              "give a larger --voxel-size",
                              (unsigned long long)run.o.max_voxels, frame, run.voxel, box.dims[0], box.dims[1],
                              box.dims[2]));
}

// The frame's media on the run's voxel size, measured; chosen again once when the frame misses the
// target (an automatic size only).
MediaVoxels voxelize_frame(ExportRun& run, const std::vector<MediaSample>& samples, int frame, ColumnError& e) {
  for (int attempt = 0;; ++attempt) {
    const VoxelBox box = media_box(samples, run.voxel);
    check_box(run, box, frame);
    MediaVoxels voxels = voxelize_media(samples, box, {has_fire(samples), colours_vary(samples)});
    e = measure_column_error(samples, voxels);
    if (e.opacity_max <= run.o.error || run.o.voxel_size > 0.0 || attempt == 1) return voxels;
    fix_voxel_size(run, samples, frame, true);
  }
}

// One frame's media voxelized, measured and written into `folder`.
void export_frame(ExportRun& run, const std::vector<MediaSample>& samples, int frame,
                  const std::filesystem::path& folder, ProgressTask& task, size_t done) {
  const std::string file = vdb_frame_file_name(run.name, frame);
  nlohmann::json row = {{"frame", frame}, {"file", file}, {"particles", samples.size()}};
  MediaVoxels voxels;
  if (!samples.empty()) {
    fix_voxel_size(run, samples, frame);
    task.stage(done, "voxelize");
    ColumnError e;
    voxels = voxelize_frame(run, samples, frame, e);
    const VoxelBox& box = voxels.box;
    run.worst_opacity = std::max(run.worst_opacity, e.opacity_max);
    run.worst_depth = std::max(run.worst_depth, e.depth_max);
    run.largest_grid = std::max(run.largest_grid, box.voxels());
    row.update({{"voxel_size", box.voxel}, {"voxels", box.voxels()}, {"dims", box.dims},
                {"opacity_error", e.opacity_max}, {"opacity_rms", e.opacity_rms}, {"depth_error", e.depth_max},
                {"depth_peak", e.depth_peak}, {"temperature", !voxels.temperature.empty()},
                {"color", !voxels.color.empty()}});
  }
  task.stage(done, "write");
  write_vdb_grids((folder / file).string(), media_vdb_grids(voxels));
  run.rows.push_back(row);
}

// Runs the opened scene to every frame of `range`, exporting each into `folder`.
void export_frames(ExportRun& run, SceneRuntime& runtime, const FrameRange& range, const std::filesystem::path& folder,
                   ProgressSink* progress) {
  ProgressTask task(progress, "pyro export-vdb", size_t(range.count()));
  for (int f = range.first; f <= range.last; ++f) {
    const size_t done = size_t(f - range.first);
    task.stage(done, "simulate");
    const uint64_t target = runtime.sequencer().runtime_frame(f);
    while (runtime.frame() <= target) runtime.simulate_step();
    export_frame(run, world_media(runtime.world()), f, folder, task, done);
    task.update(done + 1);
  }
}

std::string voxel_choice_text(const ExportRun& run) {
  std::string text = format_text("chosen in %d tries", run.tries);
  for (const auto& later : run.sizes)
    text += format_text("; %g from frame %d", later["voxel_size"].get<double>(), later["from_frame"].get<int>());
  return text;
}

VdbExportReport report_of(const ExportRun& run, const FrameRange& range, double seconds) {
  const VdbExportOptions& o = run.o;
  VdbExportReport r;
  r.json = {{"scene", o.scene}, {"out", o.out}, {"pattern", vdb_sequence_pattern(run.name)},
            {"first_frame", range.first}, {"last_frame", range.last}, {"files", range.count()},
            {"voxel_size", run.first_voxel}, {"voxel_size_chosen", o.voxel_size <= 0.0}, {"voxel_sizes_later", run.sizes},
            {"error_target", o.error},
            {"opacity_error_max", run.worst_opacity}, {"depth_error_max", run.worst_depth},
            {"error_met", run.worst_opacity <= o.error}, {"largest_grid_voxels", run.largest_grid},
            {"seconds", seconds}, {"frames", run.rows}};
  r.text = format_text(
      "exported frames %d..%d of %s as %s/%s (files %s..%s) in %.2f s\n"
      "voxel size %g (%s), largest grid %llu voxels\n"
      "column opacity error %.4g max over the frames (target %g, %s), optical depth error %.4g\n",
      range.first, range.last, o.scene.c_str(), o.out.c_str(), vdb_sequence_pattern(run.name).c_str(),
      vdb_frame_file_name(run.name, range.first).c_str(), vdb_frame_file_name(run.name, range.last).c_str(), seconds,
      run.first_voxel, o.voxel_size > 0.0 ? "given" : voxel_choice_text(run).c_str(),
      (unsigned long long)run.largest_grid, run.worst_opacity, o.error, run.worst_opacity <= o.error ? "met" : "NOT met",
      run.worst_depth);
  return r;
}

}  // namespace

VdbExportReport run_vdb_export(const VdbExportOptions& o, const NoteSink& note, ProgressSink* progress) {
  const auto t0 = Clock::now();
  check_numbers(o);
  const FrameRange range = parse_frame_range(o.frames, "--frames");
  if (!o.name.empty()) check_vdb_sequence_name(o.name, "--name");
  const SceneDescription scene = load_scene(o.scene);
  OutputGate()
      .reads(scene_inputs(o.scene, scene))
      .writes({o.out, "--out", OutputShape::folder, vdb_export_output_kind(), o.overwrite})
      .check();
  ExportRun run(o, o.name.empty() ? vdb_sequence_name_for(scene.name) : o.name);
  OpenSceneOptions open;
  open.description = scene;
  open.on_note = note;
  open.runtime.on_note = note;
  open.runtime.readback = false;
  const OpenedScene opened = open_scene(o.scene, open);
  FolderReplacement staged(o.out, vdb_export_output_kind(), o.overwrite);
  export_frames(run, *opened.runtime, range, staged.path(), progress);
  staged.commit();
  if (run.worst_opacity > o.error && note)
    note(format_text("%s: the column opacity error %.4g is over the target %g at voxel size %g", o.out.c_str(),
                     run.worst_opacity, o.error, run.voxel));
  return report_of(run, range, seconds_since(t0));
}

}  // namespace pyro
