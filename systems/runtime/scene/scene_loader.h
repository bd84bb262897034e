#pragma once
// Reads a scene file (JSON, described in docs/scene_format.md) into a SceneDescription and
// checks every value: type, range, array length, unknown keys (with a "did you mean"),
// and the checks that involve several fields (near < far, box_min < box_max, ...).
//
// Every problem throws pyro::UserError(file, place, message) where place is a JSON pointer
// (RFC 6901, e.g. "/clouds/2/radius"; empty for the whole document or the file itself) or
// "line L, column C" for a JSON syntax error, and message says what was expected and what
// was found. Nothing is silently clamped or defaulted: a key that is present must be valid.
#include <string>

#include "systems/runtime/scene/scene_description.h"

namespace pyro {

// Reads and parses the file at `path`. SceneDescription::file is set to `path`.
SceneDescription load_scene(const std::string& path);

// The bytes of the scene file at `path` ("-": standard input), as load_scene reads them; a
// missing, unreadable or non-regular file is a UserError naming it.
std::string read_scene_text(const std::string& path);

// Parses scene JSON held in memory; `file_name_for_messages` names it in errors and is
// stored in SceneDescription::file.
SceneDescription parse_scene(const std::string& text, const std::string& file_name_for_messages);

}  // namespace pyro
