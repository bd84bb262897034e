#pragma once
// A run's identity is its content: the scene as parsed (SceneDescription::content_digest), the
// content digest of every asset it reads (volume files, flipbook folders), the settings that
// change the pixels and the engine (version, build ID, shaders). Output folders are keyed on it
// (engine/io/output_folder.h): a folder holds one identity's frames, a resume keeps a frame only
// when its identity is the run's, and ranges of one identity (a farm's) add to one folder.
// Neither the scene file's path nor its bytes count: the same scene from a pipe, a copy or a
// reformatted file is the same run; an edited scene or an asset replaced in place is another.
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/content_digest.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct RunIdentity {
  nlohmann::json parts;  // {"scene", "assets": {pointer: digest}, "settings", "engine"}
  std::string digest;    // SHA-256 of parts' canonical text
};

// The identity of running `scene` with `settings` (a JSON object: whatever changes the pixels).
// Assets' digests come from `digests` (cached by size and modification time); a fire without a
// `flipbook` counts the default flipbook's folder (default_flipbook.h), which the caller has had
// baked first (prepare_scene_run, systems/runtime/open_scene/open_scene.h): the identity bakes
// nothing. `engine_version` is the program's release (e.g. "0.1.0").
RunIdentity run_identity(const SceneDescription& scene, const nlohmann::json& settings,
                         const std::string& engine_version, DigestCache& digests);

// The scene file a run was made from, as an output folder's manifest records it beside the
// identity (not part of it): {"path": its canonical path, "file": "DEVICE:INODE"}. A render of an
// edited scene into the folder of its earlier render replaces that render (OutputFolder). Null
// for a scene that is no regular file (standard input, a pipe): nothing says it is the same.
nlohmann::json scene_source(const std::string& scene_path);

// What differs between two identities' parts, for a message: "the scene", "the asset at
// /volumes/0", "the settings (width 64 -> 48)", "the engine"; "an identity pyro no longer
// reads" when `before` is not one.
std::string identity_difference(const nlohmann::json& before, const nlohmann::json& now);

}  // namespace pyro
