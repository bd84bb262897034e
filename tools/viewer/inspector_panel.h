#pragma once
// The inspector (Dear ImGui): the scene's entities (camera, lights, clouds, volumes, emitters,
// fires, meshes, and the scene-wide objects) and every key of each, each with a widget chosen
// from its key table (systems/runtime/scene/scene_keys.h): sliders within the loader's ranges, colour
// pickers, vectors, choices, nested objects, and a plot with a JSON field for the life curves.
// Keys the file does not write show their default, greyed; editing one writes it. The panel only
// asks for changes: the viewer applies them through the scene document, which refuses what the
// loader refuses (its message is shown in the panel).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/io/parameter_table.h"
#include "tools/viewer/docked_panel.h"
#include "tools/viewer/inspector_edit.h"

namespace pyro {

// What the panel shows beside the keys.
struct InspectorStatus {
  std::string file;
  bool modified = false;
  bool can_undo = false, can_redo = false;
  std::string error;    // the last refused edit or failed save
  std::string message;  // the last save
};

// What the user asked for this frame.
struct InspectorRequest {
  std::optional<InspectorEdit> edit;
  bool undo = false, redo = false, save = false;
  std::string save_as;  // non-empty: save to this path
  std::string error;    // a value the panel itself could not read (text that is not JSON)
};

// The widgets of `table`'s keys for the object at `tokens` in `tree` (absent keys greyed, with
// their defaults): the inspector's, for other panels that edit part of the scene.
void draw_scene_keys(const ParameterTable& table, const nlohmann::json& tree,
                     const std::vector<std::string>& tokens, InspectorRequest& request);

class InspectorPanel {
 public:
  // `focus`: a JSON pointer (e.g. "/clouds/0") whose nodes open when first shown; empty: none.
  explicit InspectorPanel(std::string focus = {}) : focus_(std::move(focus)) {}

  // Draws the panel at its place in the column for `tree` (the document's JSON) described by
  // `table` (the scene's keys).
  InspectorRequest draw(const nlohmann::json& tree, const ParameterTable& table,
                        const InspectorStatus& status, DockedPanel& panel);

 private:
  std::string focus_;
  std::string save_as_path_;
};

}  // namespace pyro
