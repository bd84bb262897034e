#include "tools/authoring/scene_document.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "engine/core/user_error.h"
#include "engine/io/durable_file.h"
#include "engine/io/json_document.h"
#include "engine/io/json_text_edit.h"
#include "systems/runtime/scene/scene_loader.h"

namespace pyro {

SceneDocument::SceneDocument(std::string path, std::string text, Loaded loaded)
    : path_(std::move(path)),
      text_(std::move(text)),
      saved_text_(text_),
      tree_(std::move(loaded.tree)),
      description_(std::move(loaded.description)) {}

SceneDocument SceneDocument::open(const std::string& path) {
  std::string text = read_scene_text(path);
  Loaded loaded = load(text, path);
  return SceneDocument(path, std::move(text), std::move(loaded));
}

// The loader's checks first (its UserError, when it refuses, is what the caller sees); the tree
// of text it accepted then parses.
SceneDocument::Loaded SceneDocument::load(const std::string& text, const std::string& path) {
  Loaded loaded;
  loaded.description = parse_scene(text, path);
  loaded.tree = parse_json_document(text).root;
  return loaded;
}

// The bytes that differ between `before` and `after`: what lies between their common prefix and
// their common suffix.
SceneDocument::Change SceneDocument::difference(const std::string& before, const std::string& after,
                                                const std::string& pointer) {
  const std::size_t shorter = std::min(before.size(), after.size());
  std::size_t prefix = 0;
  while (prefix < shorter && before[prefix] == after[prefix]) ++prefix;
  std::size_t suffix = 0;
  while (suffix < shorter - prefix &&
         before[before.size() - 1 - suffix] == after[after.size() - 1 - suffix]) {
    ++suffix;
  }
  return {pointer, prefix, before.substr(prefix, before.size() - prefix - suffix),
          after.substr(prefix, after.size() - prefix - suffix)};
}

std::string SceneDocument::apply(const std::string& text, std::size_t offset,
                                 const std::string& removed, const std::string& inserted) {
  if (offset > text.size() || text.compare(offset, removed.size(), removed) != 0) {
    throw std::logic_error("SceneDocument: an undo step does not match the text");
  }
  return text.substr(0, offset) + inserted + text.substr(offset + removed.size());
}

void SceneDocument::become(std::string text, Loaded loaded) {
  text_ = std::move(text);
  tree_ = std::move(loaded.tree);
  description_ = std::move(loaded.description);
}

void SceneDocument::set(const std::string& pointer, const nlohmann::json& value, bool coalesce) {
  JsonTextEdit edit = set_json_value(text_, pointer, value);
  if (edit.failed()) throw UserError(path_, pointer, edit.error);
  Loaded loaded = load(edit.text, path_);

  const bool merge = coalesce && coalescing_ && !undo_.empty() && undo_.back().pointer == pointer;
  if (merge) {
    const Change& last = undo_.back();
    const std::string before = apply(text_, last.offset, last.inserted, last.removed);
    undo_.back() = difference(before, edit.text, pointer);
  } else {
    undo_.push_back(difference(text_, edit.text, pointer));
  }
  redo_.clear();
  become(std::move(edit.text), std::move(loaded));
  last_changed_ = {pointer};
  coalescing_ = coalesce;
}

void SceneDocument::undo() {
  if (undo_.empty()) throw std::logic_error("SceneDocument::undo: nothing to undo");
  step(undo_, redo_, /*forward=*/false);
}

void SceneDocument::redo() {
  if (redo_.empty()) throw std::logic_error("SceneDocument::redo: nothing to redo");
  step(redo_, undo_, /*forward=*/true);
}

// Applies from.back() backward (undo: `inserted` back to `removed`) or forward (redo), then moves
// it onto `to`; a text the loader refuses throws before anything changes.
void SceneDocument::step(std::vector<Change>& from, std::vector<Change>& to, bool forward) {
  const Change& change = from.back();
  std::string text = forward ? apply(text_, change.offset, change.removed, change.inserted)
                             : apply(text_, change.offset, change.inserted, change.removed);
  Loaded loaded = load(text, path_);
  become(std::move(text), std::move(loaded));
  last_changed_ = {change.pointer};
  to.push_back(std::move(from.back()));
  from.pop_back();
  coalescing_ = false;
}

void SceneDocument::save() {
  write_file_durably(path_, text_);
  saved_text_ = text_;
}

void SceneDocument::save_as(const std::string& path) {
  Loaded loaded = load(text_, path);
  write_file_durably(path, text_);
  path_ = path;
  description_ = std::move(loaded.description);
  saved_text_ = text_;
}

}  // namespace pyro
