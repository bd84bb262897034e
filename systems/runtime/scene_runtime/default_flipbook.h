#pragma once
// The engine's default flame flipbook: the folder that fires without a `flipbook` play. The
// runtime only names it (its asset step, load_scene_assets.h; a run's identity, run_identity.h)
// and refuses a scene that needs it while it is not baked; the bake itself sits above the
// runtime, in the front door (systems/runtime/open_scene/flipbook_bake.h: prepare_scene_run in
// open_scene.h bakes it before a run opens), and in the build's `default_flipbook` target.
#include <string>

namespace pyro {

// Where fires without a `flipbook` find theirs: $PYRO_FLIPBOOK_DIR when set, else the build
// folder's flipbooks/fire (baked by the build's `default_flipbook` target), or
// <prefix>/share/pyrocumulus/flipbooks/fire in an installed package
// (engine/core/content_location.h).
std::string default_flipbook_folder();

// Whether the default flipbook's folder holds its manifest (else the front door bakes it).
bool default_flipbook_baked();

}  // namespace pyro
