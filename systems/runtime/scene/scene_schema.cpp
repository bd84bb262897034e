#include "engine/io/parameter_schema.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

nlohmann::json scene_schema() {
  nlohmann::json schema = {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
                           {"$id", "https://pyrocumulus.invalid/scene.schema.json"},
                           {"title", "Pyrocumulus scene"}};
  schema.update(object_schema(scene_keys()));
  return schema;
}

}  // namespace pyro
