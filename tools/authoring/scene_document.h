#pragma once
// A scene file being edited (the viewer's inspector, `pyro view --set-at`): its text, the JSON
// tree and the description the loader makes of it, changed one value at a time. Every change goes
// through the loader (parse_scene), so the document never holds a scene the loader would refuse;
// every change can be undone and redone; saving writes the text back durably.
//
// The text is edited, not the tree (engine/io/json_text_edit.h): after any sequence of changes,
// every byte outside the changed values is as it was (key order, spacing, the spelling of
// untouched numbers), so a saved file differs from the original only where it was edited.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "systems/runtime/scene/scene_description.h"

namespace pyro {

class SceneDocument {
 public:
  // Reads `path`; UserError (the loader's, naming file and place) when it does not load.
  static SceneDocument open(const std::string& path);

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }              // the current text
  const nlohmann::json& tree() const { return tree_; }           // parsed from text()
  const SceneDescription& description() const { return description_; }  // parse_scene(text(), path())

  // Sets the value at `pointer` (RFC 6901). An existing value's text is replaced in place (by
  // json_text_edit's compact form; a value equal to the present one keeps its text); an absent
  // key of an existing object is added as its last key (indented like its siblings); anything
  // else (missing parent, index past the end) is a UserError naming the pointer. The new text
  // must load (parse_scene): otherwise the loader's UserError is thrown and the document (text,
  // tree, description, history) is unchanged.
  // Each set is one undo step, even one that leaves the text as it was. coalesce: when the last
  // change was a set of the same pointer also made with coalesce, this one replaces it in the
  // undo history (a slider being dragged is one undo step); an undo or redo in between ends it.
  void set(const std::string& pointer, const nlohmann::json& value, bool coalesce = false);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  // std::logic_error when nothing to undo/redo. The text goes back (forth) byte for byte; the
  // loader checks it again (a file it names may have gone since), and when it refuses, its
  // UserError is thrown and the document is unchanged. A set after an undo drops the redo steps.
  void undo();
  void redo();

  // The JSON pointers of the values the last set/undo/redo changed (for deciding what to
  // rebuild); empty after open.
  const std::vector<std::string>& last_changed() const { return last_changed_; }

  // text() differs from what was last read or saved.
  bool modified() const { return text_ != saved_text_; }

  // Writes text() atomically (engine/io/durable_file.h) to path(): a reader sees the old file or
  // the new one, never a mix. IoError/UserError on failure, the file untouched.
  void save();
  // The same to `path`, which is the document's path from then on. The text is kept as it is;
  // relative file paths in it (volumes, particle files, flipbooks) resolve against the scene's
  // folder, so before writing, the text is loaded as if it were at `path`: when it no longer
  // loads there (a relative file missing from the new folder), the loader's UserError is thrown
  // and nothing is written. IoError/UserError on failure, the target untouched and the document
  // still at its old path.
  void save_as(const std::string& path);

 private:
  // One undo step: `removed` replaced by `inserted` at byte `offset` of the text.
  struct Change {
    std::string pointer;
    std::size_t offset = 0;
    std::string removed, inserted;
  };
  struct Loaded {
    nlohmann::json tree;
    SceneDescription description;
  };

  SceneDocument(std::string path, std::string text, Loaded loaded);
  static Loaded load(const std::string& text, const std::string& path);
  static Change difference(const std::string& before, const std::string& after,
                           const std::string& pointer);
  static std::string apply(const std::string& text, std::size_t offset, const std::string& removed,
                           const std::string& inserted);
  void become(std::string text, Loaded loaded);
  void step(std::vector<Change>& from, std::vector<Change>& to, bool forward);

  std::string path_, text_, saved_text_;
  nlohmann::json tree_;
  SceneDescription description_;
  std::vector<Change> undo_, redo_;
  std::vector<std::string> last_changed_;
  bool coalescing_ = false;  // the last change was a set made with coalesce (of undo_.back())
};

}  // namespace pyro
