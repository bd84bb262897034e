#pragma once
// Flames from anywhere: no video ships with the engine, so a flipbook can be baked
// from its own black-body fire simulation. A small scene (content/scenes/flipbook_fire.json: a
// fire column on black, seen from the side) is rendered mono into `frames` PNG frames
// (frame_0000.png, ...; cross-faded over the wrap so that the loop does not jump; borders
// faded to black, Rose's chapter 4 preparation) plus
// `flipbook.json` (frame count, size, source scene), all written into a new folder beside `out`
// that replaces it as a whole only when complete (engine/io/folder_replacement.h): a kill leaves
// the old bake or the new one, and a bake of fewer frames leaves exactly its own.
// With an atlas grid (options.atlas_columns x atlas_rows), the same frames go into one atlas
// instead (atlas.png, tiles in row-major order from the top left: flipbook_atlas.h), with the
// medium's motion vectors from the simulation's own particle velocities in a second atlas of the
// same layout (motion.png: particle_motion_splat.h, packed as flipbook_motion.h says) and the
// sidecar atlas.json (flipbook_atlas_sidecar.h), replacing the folder the same way.
#include <string>
#include <vector>

#include "engine/io/folder_output_kind.h"
#include "systems/flipbook_fire/flipbook_frame_fade.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

class SceneRuntime;

struct FlipbookBakeOptions {
  int frames = 32;
  int width = 256;
  int height = 384;
  // A seamless loop: frames + loop_blend steps are simulated, and frame j < loop_blend becomes
  // the linear-light mix of simulated frames frames + j and j with weight w_j = (j + 1) /
  // (loop_blend + 1) on frame j, so that the last frame runs on into frame 0 as into frame
  // `frames` (a cross-fade over the wrap). 0: no blending (the loop jumps). < frames.
  int loop_blend = 8;
  // Preparation of every written frame (after the cross-fade): sides, top and base faded to
  // black (systems/flipbook_fire/flipbook_frame_fade.h).
  FrameFade fade;
  // An atlas of atlas_columns x atlas_rows tiles (both 0: a folder of frames); frames must fit.
  int atlas_columns = 0, atlas_rows = 0;
  std::string engine_version;  // recorded in the atlas sidecar
  bool overwrite = false;      // replace the folder whatever else it holds (keeping those files)
};

// A bake's folder as an output (engine/io/folder_output_kind.h): frames, an atlas or six-way
// lightmaps, each replacing the others' in a folder (bake-flipbook's three forms).
inline FolderOutputKind flipbook_bake_output_kind() {
  return {"flipbook bake",
          {".partial-*"},
          {"frame_*.png", "flipbook.json", "atlas.*", "motion.*", "six_way*"}};
}

struct FlipbookBakeResult {
  std::vector<std::string> files;  // in `out`, frames then the manifest
  double seconds = 0.0;
  int removed_leftovers = 0;         // what killed bakes had left beside `out` (removed)
  bool restored_old_folder = false;  // a killed bake's old folder put back before this one
};

// What a bake refuses before anything runs: throws UserError naming the scene when it has
// `fires` (a bake renders simulated fire, not flipbooks), `out` when it is a file,
// "--loop-blend" when it is not below the frame count, or "--atlas" when the frames do not fit.
void check_flipbook_bake(const SceneDescription& scene, const FlipbookBakeOptions& options,
                         const std::string& out);

// How a bake runs its scene: mono, at the flipbook's size, nothing read back.
RuntimeOptions flipbook_runtime_options(const FlipbookBakeOptions& options);

// Bakes from `runtime`, a scene checked by check_flipbook_bake and opened with
// flipbook_runtime_options (pyro bake-flipbook opens it through the front door,
// systems/runtime/open_scene/open_scene.h, so that a quality target's pick applies), still at frame 0.
FlipbookBakeResult bake_flipbook(SceneRuntime& runtime, const FlipbookBakeOptions& options,
                                 const std::string& out);

// Checks, opens `scene` as it is written (no quality pick: open_runtime, open_scene.h) and bakes.
FlipbookBakeResult bake_flipbook(const SceneDescription& scene, const FlipbookBakeOptions& options,
                                 const std::string& out);

// The default flipbook's folder (default_flipbook_folder(),
// systems/runtime/scene_runtime/default_flipbook.h), baked from content/scenes/flipbook_fire.json
// with the default options first when it holds no manifest yet (a fresh clone's first run; a note
// to `on_note` before the bake starts). The front door calls it before a run opens
// (prepare_scene_run, open_scene.h); the bake runs its own runtime, opened through the door,
// never inside a runtime being built.
std::string ensure_default_flipbook(const NoteSink& on_note = {});

}  // namespace pyro
