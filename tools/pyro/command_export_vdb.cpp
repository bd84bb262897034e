// pyro export-vdb SCENE --out DIR [--frames N | A:B] [--name NAME] [--error E] [--voxel-size H]
//                 [--overwrite] [--json]
// A scene's particle media as an OpenVDB sequence (NAME.0001.vdb, ...) for Houdini and Blender:
// tools/export/vdb_export.h does the work; this parses, calls and prints.
#include <memory>
#include <string>

#include "tools/export/vdb_export.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct ExportVdbArgs {
  VdbExportOptions options;
  bool json = false;
};

}  // namespace

void add_export_vdb_command(CLI::App& app) {
  auto a = std::make_shared<ExportVdbArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export-vdb", "Write a scene's particle media, frame by frame, as OpenVDB grids (density, temperature, color)");
  cmd->add_option("scene", a->options.scene, "Scene file")->required();
  cmd->add_option("--out", a->options.out, "Folder for NAME.0001.vdb, NAME.0002.vdb, ... (replaced whole)")->required();
  cmd->add_option("--frames", a->options.frames,
                  "N (frames 0..N-1) or A:B (frames A..B; those before are simulated); default 1. Frame f is file f+1");
  cmd->add_option("--name", a->options.name, "The files' name (default: the scene's name)");
  cmd->add_option("--error", a->options.error,
                  "Largest column opacity difference between the grid and the particles, in (0, 1] (default 0.01)");
  cmd->add_option("--voxel-size", a->options.voxel_size,
                  "Voxel side in world units (default: the largest that meets --error, measured)");
  cmd->add_flag("--overwrite", a->options.overwrite, "Replace --out even when it holds files no export wrote (they are kept)");
  cmd->add_flag("--json", a->json, "Print a JSON summary");
  cmd->callback([a] {
    const VdbExportReport r = run_vdb_export(a->options, print_note, terminal_progress());
    write_stdout(a->json ? r.json.dump() + "\n" : r.text);
  });
}

}  // namespace pyro::cli
