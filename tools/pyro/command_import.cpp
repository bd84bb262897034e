// pyro import-vdb FILE [--grid NAME | --grid-index I] [--temperature-grid NAME|none] [--error E]
//                 --out FILE [--json] [--width W] [--height H] [--samples N]
// Reads one float grid, imports it as anisotropic Gaussian particles fitted to the grid until the
// image error from every side meets the target (tools/import/vdb_file_import.h, fitted_import.h: the splats
// drawn by the real GL renderer, offscreen, against the CPU reference render of the grid from
// seven views around it), and only then writes the particle file (engine/io/particle_file.h: checked as the loader checks it, then
// written durably).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/file_kind.h"
#include "engine/core/printable_text.h"
#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/io_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/vdb_reader.h"
#include "systems/runtime/cloud_import/vdb_sequence_members.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/import_sequence.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"
#include "tools/import/vdb_file_import.h"

namespace pyro::cli {

namespace {

struct ImportArgs {
  std::string file, grid, out;
  std::string temperature_grid;  // empty: the first of kTemperatureGridNames; "none": off
  int grid_index = -1;
  double error = 0.03;
  int width = 256, height = 256;
  int samples = 256;  // the path-traced truth's paths per pixel (grids too large for a dense box)
  bool json = false;
  bool list = false;
  bool overwrite = false;   // sequences: replace --out whatever else it holds
  double fps = 24.0;        // sequences: the source's frames per second
  double extinction = 0.0;  // sequences: 0 is automatic
};

// --list: what the file holds, one grid a line (or a JSON array), nothing written.
void list_grids(const ImportArgs& a) {
  const std::vector<VdbGridInfo> grids = list_vdb_grids(a.file);
  nlohmann::json out = nlohmann::json::array();
  for (const VdbGridInfo& g : grids) {
    out.push_back({{"index", g.index}, {"name", g.name}, {"value_type", g.value_type},
                   {"class", g.grid_class}, {"half_float", g.half_float},
                   {"voxel_size", g.voxel_size}, {"active_voxels", g.active_voxels},
                   {"bbox_min", g.bbox_min}, {"bbox_max", g.bbox_max},
                   {"importable", g.is_float() && g.affine}});
    if (!a.json)
      std::printf("[%d] \"%s\" %s %s%s, %llu active voxels, voxel size %g x %g x %g%s\n", g.index,
                  g.name.c_str(), g.value_type.c_str(), g.grid_class.c_str(),
                  g.half_float ? " (half float)" : "",
                  static_cast<unsigned long long>(g.active_voxels), g.voxel_size[0], g.voxel_size[1],
                  g.voxel_size[2], g.is_float() && g.affine ? "" : "  [cannot be imported]");
  }
  if (a.json) write_stdout(nlohmann::json{{"file", a.file}, {"grids", out}}.dump() + "\n");
}

// Prints the summary of an import written.
void print_import(const ImportArgs& a, const VdbFileImport& import) {
  const nlohmann::json& summary = import.summary;
  const GridHeader& grid = import.grid;
  const double seconds = import.seconds;
  if (a.json) {
    write_stdout(summary.dump() + "\n");
  } else if (summary["measured"].get<bool>()) {
    std::printf("%s: %llu active voxels -> %llu particles, image RMSE over %d views mean %.4f, max %.4f "
                "(target %g %s), %.3f s; wrote %s\n",
                printable(a.file).c_str(), (unsigned long long)grid.active_voxels, summary["particles"].get<unsigned long long>(),
                summary["views"].get<int>(), summary["rmse_views_mean"].get<double>(),
                summary["rmse_views_max"].get<double>(), a.error, summary["target_met"].get<bool>() ? "met" : "not met",
                seconds, printable(a.out).c_str());
  } else {
    std::printf("%s: %llu active voxels -> %llu particles (error not measured), %.3f s; wrote %s\n", printable(a.file).c_str(),
                (unsigned long long)grid.active_voxels, summary["particles"].get<unsigned long long>(), seconds,
                printable(a.out).c_str());
  }
}

void say(const ImportArgs& a, const std::string& what) {
  std::fprintf(stderr, "pyro import-vdb: %s: %s\n", printable(a.file).c_str(), printable(what).c_str());
}

// Everything about the output that can be wrong is found before the import (seconds to minutes).
void check_destination(const ImportArgs& a) {
  if (a.out.empty()) throw UserError("", "--out", "the particle file to write (.pyrop)");
  char found[64];
  std::snprintf(found, sizeof found, "%g", a.error);
  if (!(a.error > 0.0 && a.error <= 1.0))
    throw UserError("", "--error", std::string("a number in (0, 1], found ") + found);
  OutputGate().reads(a.file, "the VDB file being imported").writes_file(a.out, "--out").check();
  if (const int removed = remove_stale_temporaries(a.out); removed > 0)
    say(a, "removed " + std::to_string(removed) + " temporary file(s) of " + a.out + " that killed runs had left");
}

void run_import(const ImportArgs& a) {
  // An animated sequence (a printf pattern, a glob or a folder): tools/pyro/import_sequence.h.
  if (names_vdb_sequence(a.file)) {
    if (a.list)
      throw UserError(a.file, "--list", "one OpenVDB file to list, found " +
                                            (std::filesystem::is_directory(a.file) ? std::string("a folder (a sequence)")
                                                                                   : std::string("a sequence pattern")));
    if (!a.temperature_grid.empty() && a.temperature_grid != "none")
      throw UserError(a.file, "--temperature-grid",
                      "one OpenVDB file: a sequence imports its density grid only (each frame's temperature is "
                      "not imported yet), found a sequence");
    return run_sequence_import({a.file, a.out, {a.grid, a.grid_index}, a.error, a.extinction, a.fps, a.json,
                                a.overwrite});
  }
  if (const std::string kind = non_regular_file_kind(a.file); !kind.empty())
    throw UserError(a.file, "", "expected an OpenVDB file, found " + kind);
  if (a.list) {
    list_grids(a);
    return;
  }
  check_destination(a);
  const VdbFileImportRequest request{a.file,  a.grid,   a.grid_index, a.temperature_grid, a.error,
                                     a.width, a.height, a.samples,    a.out};
  print_import(a, import_vdb_file(request, [&a](const std::string& what) { say(a, what); },
                                  terminal_progress()));
}

}  // namespace

void add_import_command(CLI::App& app) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* cmd = app.add_subcommand("import-vdb", "Import an OpenVDB density grid as Gaussian particles");
  cmd->add_option("file", args->file,
                  "OpenVDB file (.vdb); or a sequence: a printf pattern (\"smoke_%06d.vdb\"), a glob "
                  "(\"smoke_*.vdb\") or a folder")
      ->required();
  cmd->add_option("--grid", args->grid, "Grid name (default: \"density\", else the first float grid)");
  cmd->add_option("--grid-index", args->grid_index, "Grid position in the file, from 0 (for repeated names)");
  cmd->add_option("--temperature-grid", args->temperature_grid,
                  "Temperature grid for fire (default: \"temperature\", \"heat\" or \"flame\", the first present; "
                  "\"none\": off)");
  cmd->add_option("--error", args->error, "Image error target in (0, 1] (default 0.03)");
  cmd->add_option("--out", args->out,
                  "Particle file to write (.pyrop), or for a sequence the folder (.pyroseq); required unless --list");
  cmd->add_flag("--list", args->list, "List the file's grids (index, name, type, class, voxels) and exit");
  cmd->add_option("--width", args->width, "Width of the evaluation image (default 256)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Height of the evaluation image (default 256)")->check(CLI::Range(1, 8192));
  cmd->add_option("--samples", args->samples,
                  "Paths per pixel of the path-traced truth for grids too large for a dense box (default 256)")
      ->check(CLI::Range(2, 1 << 20));
  cmd->add_option("--fps", args->fps, "Sequences: the source's frames per second (default 24)")
      ->check(CLI::Range(1e-3, 1e6));
  cmd->add_option("--extinction", args->extinction,
                  "Sequences: extinction per unit density per world unit (default: automatic, from the first "
                  "frame with active voxels)")
      ->check(CLI::Range(1e-9, 1e9));
  cmd->add_flag("--overwrite", args->overwrite,
                "A sequence: replace --out even when it holds files no import wrote (they are kept)");
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_import(*args); });
}

}  // namespace pyro::cli
