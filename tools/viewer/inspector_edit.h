#pragma once
// An edit the inspector asks of the scene document (tools/authoring/scene_document.h): the
// value at a JSON pointer. A key whose object is not written in the file yet (a default shown in
// the inspector) is set by writing the nearest missing object around it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pyro {

struct InspectorEdit {
  std::string pointer;  // RFC 6901
  nlohmann::json value;
  bool coalesce = false;  // one step of a drag: joins the previous step of the same pointer
};

// The edit that sets `value` at `tokens` in `tree`: at `tokens` itself when its parent exists,
// otherwise at the outermost missing object, holding the value under the missing keys
// ({"a": {"b": value}}). An index into a missing or short array cannot be made: the edit stays at
// `tokens` and the document refuses it with its message.
InspectorEdit edit_creating_parents(const nlohmann::json& tree, const std::vector<std::string>& tokens,
                                    nlohmann::json value, bool coalesce);

}  // namespace pyro
