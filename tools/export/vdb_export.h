#pragma once
// pyro export-vdb: a scene's particle media, frame by frame, as an OpenVDB sequence that Houdini
// and Blender read (media_vdb.h: density as extinction per unit length, temperature, colour).
//   load the scene -> the gate (engine/io/output_gate.h: every output checked before any work)
//   -> open it (the front door, with its quality pick) -> for each frame: simulate to it
//   (frames before the range are simulated, never drawn), gather its media (world_media.h),
//   choose the voxel size at the first frame with media (voxel_size_choice.h) unless given,
//   voxelize (media_voxels.h), measure the projection error (column_error.h), write
//   NAME.NNNN.vdb (vdb_sequence_naming.h) into a staging folder that replaces --out whole when
//   every frame is written (engine/io/folder_replacement.h), so a failure leaves nothing half
//   written.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct VdbExportOptions {
  std::string scene;            // the scene file
  std::string out;              // the folder
  std::string frames = "1";     // "N" (0 .. N-1) or "A:B"
  std::string name;             // the files' name; empty: the scene's name
  double error = 0.01;          // column opacity error target, (0, 1]
  double voxel_size = 0.0;      // > 0: this size, the error measured and reported; 0: chosen
  bool overwrite = false;
  uint64_t max_voxels = uint64_t{1} << 26;  // per grid (a dense box of 256 MiB of floats)
};

struct VdbExportReport {
  nlohmann::json json;  // scene, out, pattern, frames, voxel_size, error, seconds, per-frame rows
  std::string text;     // the summary lines for stdout
};

// Throws UserError (exit 2) for a bad scene, frame range, name, error, voxel size or output, and
// IoError (exit 1) where the file system refuses; before any file is written.
VdbExportReport run_vdb_export(const VdbExportOptions& options, const NoteSink& note, ProgressSink* progress);

}  // namespace pyro
