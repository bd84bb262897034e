#pragma once
// pyro bake-flipbook SCENE --out DIR [--atlas CxR | --six-way]: one pipeline for the three bakes
// of a scene. Every kind shares the options (frames, size, loop blend), the checks (the scene
// loaded, --out not holding it, the kind's own refusals, all before anything runs), the opening
// of the scene through the front door (systems/runtime/open_scene/open_scene.h: a quality
// target's pick applied) and the report; what differs is the bake run on the opened runtime:
//   frames   flame frames in a folder (systems/runtime/open_scene/flipbook_bake.h)
//   atlas    flame frames as one atlas of COLUMNSxROWS tiles with motion vectors
//   six_way  six-way lightmaps of a lit smoke scene (tools/bake/six_way_bake.h)
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "systems/runtime/open_scene/flipbook_bake.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

enum class BakeKind { frames, atlas, six_way };

struct BakeOptions {
  std::string scene;  // scene file, "-": standard input
  std::string out;    // the folder the bake replaces as a whole
  BakeKind kind = BakeKind::frames;
  std::string atlas;  // "CxR" for BakeKind::atlas
  // Frames, size and loop blend for every kind; the atlas fields are set from `atlas`.
  FlipbookBakeOptions flipbook;
};

// The kind that --six-way and --atlas ask for; UserError when both are given.
BakeKind bake_kind(bool six_way, const std::string& atlas);

struct BakeReport {
  nlohmann::json json;  // the summary: scene, out, the options, files, seconds
  std::string text;     // its line for people
};

// Checks, opens and bakes; notes (the scene's quality pick, leftovers of killed bakes) go to
// `on_note`. Throws UserError for what the checks refuse, before anything is written.
BakeReport run_bake(BakeOptions options, const NoteSink& on_note);

}  // namespace pyro
