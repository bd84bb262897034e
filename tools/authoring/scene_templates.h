#pragma once
// The starting scenes `pyro new` writes: content/templates/NAME.json, data installed with the
// content (share/pyrocumulus/templates). Each names the schema with "$schema" and may name
// asset files (a volume's `file` and `fallback`, a fire's `flipbook`) relative to its own folder;
// a written copy has those paths rewritten to resolve from the copy's folder.
#include <string>
#include <vector>

namespace pyro::cli {

struct SceneTemplate {
  std::string name;         // the file's stem: "clouds", "smoke", ...
  std::string path;         // content/templates/NAME.json
  std::string description;  // the template's scene "name", which says what it shows
};

// Every template under the content folder's templates/, sorted by name.
std::vector<SceneTemplate> scene_templates();

// The template called `name`; a UserError at --template listing the names when there is none.
SceneTemplate find_scene_template(const std::string& name);

// The template's text for a scene file at `destination`: "$schema" and the asset paths rewritten
// as paths relative to the destination's folder (absolute ones stay as they are); everything
// else byte for byte as the template has it.
std::string scene_template_text(const SceneTemplate& t, const std::string& destination);

}  // namespace pyro::cli
