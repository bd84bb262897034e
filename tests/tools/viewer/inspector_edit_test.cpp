// The inspector's edits: a key whose object the file does not write yet is set by writing the
// nearest missing object around it.
#include "engine/io/json_text_edit.h"
#include "tools/viewer/inspector_edit.h"

#include <gtest/gtest.h>

namespace pyro {
namespace {

using nlohmann::json;

TEST(InspectorEdit, SetsInPlaceWhenTheParentExists) {
  const json tree = json::parse(R"({"camera": {"fov_y_deg": 40}, "clouds": [{"density": 0.4}]})");
  const InspectorEdit e = edit_creating_parents(tree, {"clouds", "0", "density"}, 0.6, true);
  EXPECT_EQ(e.pointer, "/clouds/0/density");
  EXPECT_EQ(e.value, json(0.6));
  EXPECT_TRUE(e.coalesce);
  // An absent key of a present object: still in place (the document adds the key).
  EXPECT_EQ(edit_creating_parents(tree, {"camera", "near"}, 0.2, false).pointer, "/camera/near");
}

TEST(InspectorEdit, WritesTheOutermostMissingObject) {
  const json tree = json::parse(R"({"camera": {"fov_y_deg": 40}})");
  const InspectorEdit stereo = edit_creating_parents(tree, {"camera", "stereo", "interocular"}, 0.1, false);
  EXPECT_EQ(stereo.pointer, "/camera/stereo");
  EXPECT_EQ(stereo.value, json::parse(R"({"interocular": 0.1})"));
  const InspectorEdit render = edit_creating_parents(tree, {"render", "fire", "t_min"}, 2000, false);
  EXPECT_EQ(render.pointer, "/render");
  EXPECT_EQ(render.value, json::parse(R"({"fire": {"t_min": 2000}})"));
}

TEST(InspectorEdit, LeavesAMissingArrayEntryToTheDocumentToRefuse) {
  const json tree = json::parse(R"({"clouds": []})");
  EXPECT_EQ(edit_creating_parents(tree, {"clouds", "2", "density"}, 0.5, false).pointer, "/clouds/2/density");
  EXPECT_EQ(edit_creating_parents(tree, {"lights", "0", "direction"}, 1, false).pointer, "/lights/0/direction");
}

TEST(InspectorEdit, EscapesPointerTokens) {
  EXPECT_EQ(json_pointer_text({"a/b", "c~d"}), "/a~1b/c~0d");
}

}  // namespace
}  // namespace pyro
