// The scene's JSON Schema (`pyro schema`, content/scene.schema.json) against the loader: the
// shipped scenes pass both, each class of mistake is refused by both, and 200 scenes mutated at
// random (fixed seed) get the same verdict from both. The schema is checked by an independent
// validator: Python's jsonschema (Debian's python3-jsonschema), run once over all files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>


#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/parameter_dictionary.h"
#include "systems/runtime/scene/scene_keys.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/file_bytes.h"
#include "tests/support/schema_validator.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path kSource = PYRO_SOURCE_DIR;

// The shipped scenes and the templates `pyro new` starts from (both name "../scene.schema.json").
std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> scenes;
  for (const char* folder : {"scenes", "templates"})
    for (const auto& entry : fs::directory_iterator(kSource / "content" / folder))
      if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

// The verdict of Python's jsonschema on each file against the shipped schema.
std::vector<std::string> schema_verdicts(const std::vector<fs::path>& files) {
  return test::jsonschema_verdicts(kSource / "content/scene.schema.json", files);
}

// The loader's verdict: empty when it accepts, else the place of its refusal and the message.
// `as_file` is the shipped scene's path, so that relative volume paths resolve as they do there.
struct LoaderVerdict {
  bool accepted = true;
  std::string place, message;
};

LoaderVerdict loader_verdict(const json& scene, const fs::path& as_file) {
  try {
    parse_scene(scene.dump(2), as_file.string());
    return {};
  } catch (const UserError& e) {
    return {false, e.place(), e.what()};
  }
}

// ---------------------------------------------------------------------------------------------
// Mutations of the five classes a schema can state: each makes a valid scene invalid.

enum class Mistake { wrong_type, out_of_range, unknown_key, missing_required, wrong_enum };
constexpr const char* kMistakeNames[] = {"wrong type", "out of range", "unknown key",
                                         "missing required key", "wrong enum"};

struct Site {  // a value present in the scene, and its key's entry
  std::string pointer;
  const ParameterKey* key;
};

struct Sites {
  std::vector<Site> values;
  std::vector<std::string> objects;  // pointers of objects read over a table
};

void collect(const json& object, const std::string& pointer, const ParameterTable& table, Sites& out) {
  out.objects.push_back(pointer);
  for (const auto& item : object.items()) {
    const ParameterKey& key = table.key(item.key());
    const std::string at = pointer + "/" + escape_pointer_token(item.key());
    out.values.push_back({at, &key});
    if (key.type == ParameterType::object) collect(item.value(), at, *key.table, out);
    if (key.type == ParameterType::objects)
      for (std::size_t i = 0; i < item.value().size(); ++i)
        collect(item.value()[i], at + "/" + std::to_string(i), *key.table, out);
  }
}

double outside(const Range& r, bool above) {
  return above ? r.hi + std::max(1.0, std::fabs(r.hi)) : r.lo - std::max(1.0, std::fabs(r.lo));
}

json out_of_range_value(const ParameterKey& key, bool above) {
  switch (key.type) {
    case ParameterType::number:
      return outside(key.range, above);
    case ParameterType::vec3:
      return json::array({outside(key.range, above), 0.0, 0.0});
    case ParameterType::unit_color:
      return 1.5;
    default:  // integer
      if (key.integer_max == std::numeric_limits<std::uint64_t>::max() || (!above && key.integer_min > 0))
        return key.integer_min > 0 ? json(key.integer_min - 1) : json(-1);
      return key.integer_max + 1;
  }
}

bool has_range(const ParameterKey& k) {
  return k.type == ParameterType::number || k.type == ParameterType::integer ||
         k.type == ParameterType::vec3 || k.type == ParameterType::unit_color;
}

struct Mutant {
  json scene;
  Mistake mistake;
  std::string pointer;  // where the loader must refuse it (a prefix of its place)
};

template <class T>
const T& pick(const std::vector<T>& items, std::mt19937_64& rng) {
  return items[std::uniform_int_distribution<std::size_t>(0, items.size() - 1)(rng)];
}

// One mutation of `mistake` somewhere in `scene`; false when the scene has no place for it.
bool mutate(const json& scene, Mistake mistake, std::mt19937_64& rng, Mutant& out) {
  Sites sites;
  collect(scene, "", scene_keys(), sites);
  std::vector<Site> candidates;
  for (const Site& s : sites.values) {
    const bool fits = mistake == Mistake::wrong_type || (mistake == Mistake::out_of_range && has_range(*s.key)) ||
                      (mistake == Mistake::missing_required && s.key->required) ||
                      (mistake == Mistake::wrong_enum && s.key->type == ParameterType::choice);
    if (fits) candidates.push_back(s);
  }
  out = {scene, mistake, ""};
  if (mistake == Mistake::unknown_key) {
    const std::string& object = pick(sites.objects, rng);
    out.scene[json::json_pointer(object)]["zz_not_a_key"] = 1;
    out.pointer = object + "/zz_not_a_key";
    return true;
  }
  if (candidates.empty()) return false;
  const Site& site = pick(candidates, rng);
  const json::json_pointer at(site.pointer);
  out.pointer = site.pointer;
  switch (mistake) {
    case Mistake::wrong_type: {
      const bool boolean = site.key->type == ParameterType::boolean;
      const bool container = site.key->type == ParameterType::object || site.key->type == ParameterType::objects;
      out.scene[at] = boolean ? json("yes") : container ? json(7) : json(true);
      break;
    }
    case Mistake::out_of_range:
      out.scene[at] = out_of_range_value(*site.key, std::bernoulli_distribution(0.5)(rng));
      break;
    case Mistake::wrong_enum:
      out.scene[at] = "not_a_choice";
      break;
    default:  // missing_required: the loader refuses at the object
      out.scene[at.parent_pointer()].erase(std::string(site.key->name));
      out.pointer = at.parent_pointer().to_string();
      break;
  }
  return true;
}

// Writes `scene` to folder/name and returns the path.
fs::path write_json(const fs::path& folder, const std::string& name, const json& scene) {
  const fs::path path = folder / name;
  std::ofstream(path) << scene.dump(2);
  return path;
}

// ---------------------------------------------------------------------------------------------

TEST(SceneSchema, CommittedSchemaIsThePyroSchemaOutput) {
  std::istringstream committed(test::read_bytes(kSource / "content/scene.schema.json"));
  std::istringstream current(scene_schema().dump(2) + "\n");
  std::string a, b;
  for (int line = 1; static_cast<bool>(std::getline(committed, a)) | static_cast<bool>(std::getline(current, b));
       ++line, a.clear(), b.clear())
    ASSERT_EQ(a, b) << "content/scene.schema.json is stale at line " << line
                    << ": run `pyro schema --out content/scene.schema.json`";
}

TEST(SceneSchema, EveryShippedSceneNamesTheSchemaAndPassesBoth) {
  const std::vector<fs::path> scenes = shipped_scenes();
  ASSERT_GE(scenes.size(), 16u);
  const std::vector<std::string> verdicts = schema_verdicts(scenes);
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const json scene = json::parse(test::read_bytes(scenes[i]));
    EXPECT_EQ(scene.value("$schema", ""), "../scene.schema.json") << scenes[i];
    EXPECT_EQ(verdicts[i], "valid") << scenes[i];
    const LoaderVerdict loader = loader_verdict(scene, scenes[i]);
    EXPECT_TRUE(loader.accepted) << loader.message;
  }
}

TEST(SceneSchema, EachClassOfMistakeIsRefusedByBoth) {
  const fs::path shipped = kSource / "content/scenes/clouds.json";
  const json scene = json::parse(test::read_bytes(shipped));
  const std::pair<Mistake, std::function<void(json&)>> mistakes[] = {
      {Mistake::wrong_type, [](json& s) { s["camera"]["fov_y_deg"] = "45"; }},
      {Mistake::out_of_range, [](json& s) { s["clouds"][0]["density"] = 2; }},
      {Mistake::unknown_key, [](json& s) { s["camera"]["fovy"] = 45; }},
      {Mistake::missing_required, [](json& s) { s["clouds"][0].erase("count"); }},
      {Mistake::wrong_enum, [](json& s) { s["render"] = {{"billboards", "sideways"}}; }},
      // A key of another mesh type, and a mesh file without its required "file".
      {Mistake::unknown_key, [](json& s) { s["meshes"] = json::parse(R"([{"type": "box", "radius": 1}])"); }},
      {Mistake::missing_required, [](json& s) { s["meshes"] = json::parse(R"([{"type": "file"}])"); }}};
  const fs::path folder = test::scratch_dir("mistakes");
  std::vector<fs::path> files;
  for (const auto& [mistake, apply] : mistakes) {
    json mutated = scene;
    apply(mutated);
    const LoaderVerdict loader = loader_verdict(mutated, shipped);
    EXPECT_FALSE(loader.accepted) << kMistakeNames[static_cast<int>(mistake)];
    files.push_back(write_json(folder, std::to_string(files.size()) + ".json", mutated));
  }
  const std::vector<std::string> verdicts = schema_verdicts(files);
  for (std::size_t i = 0; i < files.size(); ++i)
    EXPECT_EQ(verdicts[i].rfind("invalid", 0), 0u)
        << kMistakeNames[static_cast<int>(mistakes[i].first)] << ": " << verdicts[i];
}

TEST(SceneSchema, LoaderAndSchemaAgreeOnMutatedScenes) {
  const std::vector<fs::path> scenes = shipped_scenes();
  std::mt19937_64 rng(20261203);
  const fs::path folder = test::scratch_dir("mutants");
  std::vector<Mutant> mutants;
  std::vector<fs::path> origins, files;
  while (mutants.size() < 200) {
    const fs::path& origin = pick(scenes, rng);
    const auto mistake = static_cast<Mistake>(std::uniform_int_distribution<int>(0, 4)(rng));
    Mutant m;
    if (!mutate(json::parse(test::read_bytes(origin)), mistake, rng, m)) continue;
    files.push_back(write_json(folder, std::to_string(mutants.size()) + ".json", m.scene));
    origins.push_back(origin);
    mutants.push_back(std::move(m));
  }
  const std::vector<std::string> schema = schema_verdicts(files);
  int agree = 0, per_class[5] = {};
  for (std::size_t i = 0; i < mutants.size(); ++i) {
    const LoaderVerdict loader = loader_verdict(mutants[i].scene, origins[i]);
    const bool schema_accepts = schema[i] == "valid";
    const char* what = kMistakeNames[static_cast<int>(mutants[i].mistake)];
    EXPECT_EQ(loader.accepted, schema_accepts)
        << "mutant " << i << " of " << origins[i].filename() << " (" << what << " at " << mutants[i].pointer
        << "): loader " << (loader.accepted ? "accepts" : loader.message) << "; schema: " << schema[i];
    // Every mutation makes the scene invalid, and the loader says so where the mutation is.
    EXPECT_FALSE(loader.accepted) << "mutant " << i << " (" << what << " at " << mutants[i].pointer << ")";
    EXPECT_EQ(loader.place.rfind(mutants[i].pointer, 0), 0u)
        << "mutant " << i << " (" << what << "): refused at " << loader.place << ", mutated at "
        << mutants[i].pointer << ": " << loader.message;
    if (loader.accepted == schema_accepts) ++agree;
    ++per_class[static_cast<int>(mutants[i].mistake)];
  }
  std::printf("loader and schema agree on %d of %zu mutated scenes (", agree, mutants.size());
  for (int c = 0; c < 5; ++c) std::printf("%s%s: %d", c ? ", " : "", kMistakeNames[c], per_class[c]);
  std::printf(")\n");
}

TEST(SceneKeys, AReadOfAKeyTheTableDoesNotDeclareIsAProgrammingError) {
  const std::string file = "t.json";
  const json empty = json::object();
  ObjectReader reader(empty, Where{&file, ""}, camera_keys());
  float value = 0.0f;
  EXPECT_THROW(reader.number("fov_x_deg", value), std::logic_error);
  glm::vec3 v{};
  EXPECT_THROW(reader.vec3("fov_y_deg", v), std::logic_error);  // declared as a number
  EXPECT_NO_THROW(reader.number("fov_y_deg", value));
}

TEST(SceneKeys, TheSchemasDefaultsAreWhatTheLoaderGivesForAbsentKeys) {
  // Each default the camera table states, written out, reads back as the absent key's value.
  const json schema = scene_schema();
  const json& camera = schema["properties"]["camera"]["properties"];
  json written = json::object();
  for (const auto& [name, key] : camera.items())
    if (key.contains("default")) written[name] = key["default"];
  ASSERT_GE(written.size(), 7u);
  const SceneDescription absent = parse_scene("{}", "a.json");
  const SceneDescription given = parse_scene(json{{"camera", written}}.dump(), "b.json");
  EXPECT_EQ(given.camera.position, absent.camera.position);
  EXPECT_EQ(given.camera.fov_y_deg, absent.camera.fov_y_deg);
  EXPECT_EQ(given.camera.near, absent.camera.near);
  EXPECT_EQ(given.camera.far, absent.camera.far);
  EXPECT_EQ(given.camera.up, absent.camera.up);
}

}  // namespace
}  // namespace pyro
