#pragma once
// A scene's frames rendered into an output folder, as `pyro render` does: each frame drawn is
// read back once and handed to the output sinks the request asks for (systems/output/
// frame_output.h): PNG or EXR frames in the folder, and a video.
// The folder has one writer at a time and a manifest keyed on the run's identity (its content:
// systems/runtime/scene_runtime/render_identity.h; engine/io/output_folder.h). Frames are
// rendered into a temporary folder inside it and moved into place only when every frame has been
// written: a failure (or a refusal) leaves it as it was. With OutputFolderOptions::resume, the
// frames a killed run of the same identity finished, and those the folder already holds with the
// SHA-256 its manifest records, are kept and only the others drawn (still simulated from frame 0: the same bytes as an
// uninterrupted run). A quality target (scene key quality.max_rmse) is picked once for the run
// and recorded with it before anything is drawn; every range of the run draws with that pick.
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "engine/io/output_folder.h"
#include "engine/io/video_file.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/frame_range.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct FolderRenderRequest {
  std::string scene_path;  // as given (the manifest's identity names it)
  std::string out;         // the output folder
  int width = 0, height = 0;   // 0: the scene's
  std::string trace;           // a Chrome trace-event JSON file of the run; empty: none
  std::string format = "png";  // png|exr
  bool depth = false;          // EXR frames with a view-depth channel Z
  std::string video;           // the frames encoded as they are rendered; empty: none
  int video_quality = VideoWriter::default_quality;
  OutputFolderOptions folder;  // wait, overwrite, resume
  RuntimeOptions runtime;
};

struct FolderRender {
  nlohmann::json summary;  // the run: scene, size, files, timings, systems, quality pick, ...
  int drawn = 0;           // frames drawn by this run (the rest of the range kept)
};

// Renders `range` of `scene` (loaded from request.scene_path, its arguments already checked)
// into request.out. Notes (what the folder held and what becomes of it, the quality pick) go to
// `note`; the frames drawn are reported to `progress` (may be null).
FolderRender render_to_folder(const FolderRenderRequest& request, const SceneDescription& scene,
                              const FrameRange& range, const NoteSink& note,
                              ProgressSink* progress);

}  // namespace pyro
