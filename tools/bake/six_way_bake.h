#pragma once
// pyro bake-flipbook SCENE --out DIR --six-way: six-way lightmaps (six_way_basis.h) of a lit
// smoke scene (content/scenes/six_way_smoke.json: white smoke on black, seen from the front).
// Every simulated frame is drawn seven times from the same state (six_way_passes.h: a white sun
// along +x, +y, -z, -x, -y, +z of the camera's frame, then ambient light alone for the opacity)
// and packed as Unity's two textures (six_way_frame.h), written as two flipbook folders
//   DIR/six_way_a/frame_0000.png ...  (right, top, back, alpha)
//   DIR/six_way_b/frame_0000.png ...  (left, bottom, front, emissive)
// with DIR/six_way.json stating the packing, into a new folder that replaces DIR as a whole
// when complete (engine/io/folder_replacement.h), as the flame bake does. The loop is
// cross-faded over its wrap as the flame bake's (cross_fade_six_way); the borders are not faded.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/runtime_options.h"
#include "tools/bake/six_way_frame.h"
#include "tools/bake/six_way_passes.h"

namespace pyro {

class SceneRuntime;

struct SixWayBakeOptions {
  int frames = 32;
  int width = 256;
  int height = 384;
  int loop_blend = 8;  // as FlipbookBakeOptions::loop_blend
  bool overwrite = false;  // as FlipbookBakeOptions::overwrite
};

struct SixWayBakeResult {
  std::vector<std::string> files;  // in `out`: the A frames, the B frames, the sidecar
  double seconds = 0.0;
  int removed_leftovers = 0;
  bool restored_old_folder = false;
};

// What a six-way bake refuses before anything runs (UserError): a scene with flipbook `fires`,
// without `shadows` (the passes light the media), without a directional or an ambient light;
// `out` when it is a file; "--loop-blend" not below the frame count.
void check_six_way_bake(const SceneDescription& scene, const SixWayBakeOptions& options,
                        const std::string& out);

// Mono, at the bake's size, each frame read back (the passes are measured in linear light).
RuntimeOptions six_way_runtime_options(const SixWayBakeOptions& options);

// The runtime's last drawn state drawn again under `pass` (the scene's lights put back after).
RgbImage render_six_way_pass(SceneRuntime& runtime, const SixWayPassLight& pass);

// The seven passes of the runtime's last drawn state, as a frame.
SixWayFrame render_six_way_frame(SceneRuntime& runtime);

// The sidecar's text: what the textures hold and how to blend them.
nlohmann::json six_way_sidecar(const SceneDescription& scene, const SixWayBakeOptions& options);

// Bakes from `runtime` (checked by check_six_way_bake, opened with six_way_runtime_options, at
// frame 0) into `out`.
SixWayBakeResult bake_six_way(SceneRuntime& runtime, const SixWayBakeOptions& options,
                              const std::string& out);

}  // namespace pyro
