#include "systems/runtime/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "components/light_block.h"
#include "engine/core/user_error.h"

namespace pyro {
namespace {

const std::string kSceneLoaderFile = "content/scenes/test_scene.json";

// Parses `text`, expects a UserError naming kSceneLoaderFile at `place`, whose message contains every
// fragment. Returns the message for further checks.
std::string expect_error_scene_loader(const std::string& text, const std::string& place,
                         std::initializer_list<std::string> fragments) {
  try {
    parse_scene(text, kSceneLoaderFile);
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), kSceneLoaderFile) << what;
    EXPECT_EQ(e.place(), place) << what;
    EXPECT_NE(what.find(kSceneLoaderFile), std::string::npos) << what;
    if (!place.empty()) {
      EXPECT_NE(what.find("at " + place + ":"), std::string::npos) << what;
    }
    for (const std::string& f : fragments)
      EXPECT_NE(what.find(f), std::string::npos) << "missing [" << f << "] in: " << what;
    return what;
  }
  ADD_FAILURE() << "no error for: " << text;
  return {};
}

void expect_vec3(const glm::vec3& v, float x, float y, float z) {
  EXPECT_FLOAT_EQ(v.x, x);
  EXPECT_FLOAT_EQ(v.y, y);
  EXPECT_FLOAT_EQ(v.z, z);
}

// A scratch directory removed at the end of each test.
class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::temp_directory_path() /
            ("pyro_scene_loader_test_" +
             std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path p = path_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// ---------------------------------------------------------------------------------------------
// Valid scenes

const char* const kFullScene = R"({
  "name": "fog",
  "seed": 7,
  "output": {"width": 640, "height": 480, "fps": 24},
  "background": [0.5, 0.6, 0.7],
  "camera": {"position": [1, 2, 10], "target": [0, 1, 0], "up": [0, 1, 0.5], "fov_y_deg": 50,
             "near": 0.25, "far": 150, "orbit_deg_per_second": -12.5},
  "light": {"direction": [0, -1, 0.2], "color": [2, 1.5, 1], "ambient": [0.1, 0.2, 0.3]},
  "footprint": {"size": 128, "intervals": 400},
  "clouds": [
    {"name": "fog", "count": 1200, "radius": 0.45, "density": 0.4, "color": 0.7,
     "box": {"min": [-10, 0, -10], "max": [10, 1, 10]}, "seed": 3, "drift": [0.1, 0, -0.2],
     "jitter": 0.05},
    {"count": 1e3, "color": [0.9, 0.8, 0.7], "seed": 18446744073709551615}
  ],
  "meshes": [
    {"type": "ground_plane", "position": [0, -0.5, 0], "scale": 30, "color": [0.2, 0.3, 0.1]},
    {"type": "water_tower", "position": [3, 0, -2], "scale": 1.5, "color": [0.6, 0.6, 0.65]}
  ]
})";

TEST(SceneLoader, FullSceneRoundTrip) {
  const SceneDescription s = parse_scene(kFullScene, kSceneLoaderFile);
  EXPECT_EQ(s.file, kSceneLoaderFile);
  EXPECT_EQ(s.name, "fog");
  EXPECT_EQ(s.seed, 7u);
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  EXPECT_FLOAT_EQ(s.frames_per_second, 24.0f);
  expect_vec3(s.background, 0.5f, 0.6f, 0.7f);

  expect_vec3(s.camera.position, 1, 2, 10);
  expect_vec3(s.camera.target, 0, 1, 0);
  expect_vec3(s.camera.up, 0, 1, 0.5f);
  EXPECT_FLOAT_EQ(s.camera.fov_y_deg, 50.0f);
  EXPECT_FLOAT_EQ(s.camera.near, 0.25f);
  EXPECT_FLOAT_EQ(s.camera.far, 150.0f);
  EXPECT_FLOAT_EQ(s.camera.orbit_deg_per_second, -12.5f);

  expect_vec3(s.directional_lights.at(0).direction, 0, -1, 0.2f);
  expect_vec3(s.directional_lights.at(0).color, 2, 1.5f, 1);
  expect_vec3(s.ambient_lights.at(0).color, 0.1f, 0.2f, 0.3f);

  EXPECT_EQ(s.footprint.size, 128);
  EXPECT_EQ(s.footprint.intervals, 400);

  ASSERT_EQ(s.clouds.size(), 2u);
  const CloudDescription& a = s.clouds[0];
  EXPECT_EQ(a.name, "fog");
  EXPECT_EQ(a.count, 1200u);
  EXPECT_FLOAT_EQ(a.radius, 0.45f);
  EXPECT_FLOAT_EQ(a.density, 0.4f);
  expect_vec3(a.color, 0.7f, 0.7f, 0.7f);  // a grey level c means (c, c, c)
  expect_vec3(a.box_min, -10, 0, -10);
  expect_vec3(a.box_max, 10, 1, 10);
  EXPECT_EQ(a.seed, 3u);
  expect_vec3(a.drift, 0.1f, 0, -0.2f);
  EXPECT_FLOAT_EQ(a.jitter, 0.05f);

  const CloudDescription& b = s.clouds[1];
  const CloudDescription defaults;
  EXPECT_EQ(b.name, "");
  EXPECT_EQ(b.count, 1000u);  // 1e3 is a whole number
  expect_vec3(b.color, 0.9f, 0.8f, 0.7f);
  EXPECT_EQ(b.seed, 18446744073709551615ull);
  EXPECT_FLOAT_EQ(b.radius, defaults.radius);
  EXPECT_FLOAT_EQ(b.density, defaults.density);
  expect_vec3(b.box_min, defaults.box_min.x, defaults.box_min.y, defaults.box_min.z);
  expect_vec3(b.box_max, defaults.box_max.x, defaults.box_max.y, defaults.box_max.z);

  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].kind, MeshKind::ground_plane);
  expect_vec3(s.meshes[0].position, 0, -0.5f, 0);
  EXPECT_FLOAT_EQ(s.meshes[0].scale, 30.0f);
  expect_vec3(s.meshes[0].color, 0.2f, 0.3f, 0.1f);
  EXPECT_EQ(s.meshes[1].kind, MeshKind::water_tower);
  expect_vec3(s.meshes[1].position, 3, 0, -2);
  EXPECT_FLOAT_EQ(s.meshes[1].scale, 1.5f);
  expect_vec3(s.meshes[1].color, 0.6f, 0.6f, 0.65f);
}

TEST(SceneLoader, EmptyObjectGivesAllDefaults) {
  const SceneDescription s = parse_scene("{}", kSceneLoaderFile);
  const SceneDescription d;
  EXPECT_EQ(s.file, kSceneLoaderFile);
  EXPECT_EQ(s.name, d.name);
  EXPECT_EQ(s.seed, d.seed);
  EXPECT_EQ(s.width, d.width);
  EXPECT_EQ(s.height, d.height);
  EXPECT_FLOAT_EQ(s.frames_per_second, d.frames_per_second);
  EXPECT_EQ(s.background, d.background);
  EXPECT_EQ(s.camera.position, d.camera.position);
  EXPECT_EQ(s.camera.target, d.camera.target);
  EXPECT_EQ(s.camera.up, d.camera.up);
  EXPECT_FLOAT_EQ(s.camera.fov_y_deg, d.camera.fov_y_deg);
  EXPECT_FLOAT_EQ(s.camera.near, d.camera.near);
  EXPECT_FLOAT_EQ(s.camera.far, d.camera.far);
  EXPECT_FLOAT_EQ(s.camera.orbit_deg_per_second, d.camera.orbit_deg_per_second);
  EXPECT_EQ(s.directional_lights.at(0).direction, d.directional_lights.at(0).direction);
  EXPECT_EQ(s.directional_lights.at(0).color, d.directional_lights.at(0).color);
  EXPECT_EQ(s.ambient_lights.at(0).color, d.ambient_lights.at(0).color);
  EXPECT_EQ(s.footprint.size, d.footprint.size);
  EXPECT_EQ(s.footprint.intervals, d.footprint.intervals);
  EXPECT_TRUE(s.clouds.empty());
  EXPECT_TRUE(s.meshes.empty());
}

TEST(SceneLoader, PartialObjectsKeepOtherDefaults) {
  const SceneDescription s = parse_scene(
      R"({"output": {"width": 320}, "camera": {"fov_y_deg": 30}, "clouds": [{"count": 5}],
          "meshes": [{"type": "water_tower"}]})",
      kSceneLoaderFile);
  const SceneDescription d;
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.height, d.height);
  EXPECT_FLOAT_EQ(s.camera.fov_y_deg, 30.0f);
  EXPECT_EQ(s.camera.position, d.camera.position);
  EXPECT_FLOAT_EQ(s.camera.far, d.camera.far);
  ASSERT_EQ(s.clouds.size(), 1u);
  const CloudDescription dc;
  EXPECT_EQ(s.clouds[0].count, 5u);
  EXPECT_FLOAT_EQ(s.clouds[0].radius, dc.radius);
  EXPECT_EQ(s.clouds[0].color, dc.color);
  EXPECT_EQ(s.clouds[0].seed, dc.seed);
  ASSERT_EQ(s.meshes.size(), 1u);
  const MeshDescription dm;
  EXPECT_EQ(s.meshes[0].kind, MeshKind::water_tower);
  EXPECT_EQ(s.meshes[0].position, dm.position);
  EXPECT_FLOAT_EQ(s.meshes[0].scale, dm.scale);
  EXPECT_EQ(s.meshes[0].color, dm.color);
}

TEST(SceneLoader, LightsListAnyNumberOfLights) {
  const SceneDescription s = parse_scene(R"({"lights": [
      {"type": "ambient", "color": [0.1, 0.2, 0.3]},
      {"type": "directional", "direction": [0, -1, 0], "color": [1, 0.5, 0.25], "intensity": 2},
      {"type": "directional", "direction": [1, 0, 0]},
      {"type": "ambient"}]})", kSceneLoaderFile);
  ASSERT_EQ(s.directional_lights.size(), 2u);
  ASSERT_EQ(s.ambient_lights.size(), 2u);
  expect_vec3(s.directional_lights[0].direction, 0, -1, 0);
  expect_vec3(s.directional_lights[0].color, 1, 0.5f, 0.25f);
  EXPECT_EQ(s.directional_lights[0].intensity, 2.0f);
  EXPECT_EQ(s.directional_lights[1].color, DirectionalLight{}.color);
  expect_vec3(s.ambient_lights[0].color, 0.1f, 0.2f, 0.3f);
  EXPECT_EQ(s.ambient_lights[1].color, AmbientLight{}.color);
  const SceneDescription dark = parse_scene(R"({"lights": []})", kSceneLoaderFile);
  EXPECT_TRUE(dark.directional_lights.empty());
  EXPECT_TRUE(dark.ambient_lights.empty());
}

TEST(SceneLoader, LightsAreCheckedLikeEveryOtherKey) {
  expect_error_scene_loader(R"({"light": {}, "lights": []})", "/lights", {"either \"light\" or \"lights\""});
  expect_error_scene_loader(R"({"lights": [{"direction": [0, -1, 0]}]})", "/lights/0", {"type"});
  expect_error_scene_loader(R"({"lights": [{"type": "spot"}]})", "/lights/0/type", {"\"directional\""});
  expect_error_scene_loader(R"({"lights": [{"type": "ambient", "direction": [0, -1, 0]}]})", "/lights/0/direction", {"unknown key"});
  expect_error_scene_loader(R"({"lights": [{"type": "directional", "direction": [0, 0, 0]}]})", "/lights/0/direction", {"non-zero"});
  expect_error_scene_loader(R"({"lights": [{"type": "directional", "intensity": -1}]})", "/lights/0/intensity", {"found -1"});
  // The light block holds kMaxSuns suns: one more is refused at load, any ambient lights are not.
  std::string suns;
  for (int i = 0; i < kMaxSuns; ++i) suns += R"({"type": "directional"}, {"type": "ambient"}, )";
  EXPECT_EQ(parse_scene(R"({"lights": [)" + suns + R"({"type": "ambient"}]})", kSceneLoaderFile).directional_lights.size(),
            size_t(kMaxSuns));
  expect_error_scene_loader(R"({"lights": [)" + suns + R"({"type": "directional"}]})", "/lights",
                            {"at most 16 directional lights, found 17"});
}

TEST(SceneLoader, ShadowsScatteringSetsTheLobeAndOctaves) {
  const SceneDescription s = parse_scene(R"({"shadows": {"scattering": {"anisotropy": 0.6, "octaves": 4,
      "attenuation": 0.3, "contribution": 0.45, "eccentricity": 0.7}}})", kSceneLoaderFile);
  ASSERT_TRUE(s.shadows.has_value());
  const SunScattering& sc = s.shadows->scattering;
  EXPECT_FLOAT_EQ(float(sc.anisotropy), 0.6f);
  EXPECT_EQ(sc.octaves.octaves, 4);
  EXPECT_FLOAT_EQ(float(sc.octaves.attenuation), 0.3f);
  EXPECT_FLOAT_EQ(float(sc.octaves.contribution), 0.45f);
  EXPECT_FLOAT_EQ(float(sc.octaves.eccentricity), 0.7f);
  // Without the key: one isotropic octave, single scattering.
  EXPECT_EQ(parse_scene(R"({"shadows": {}})", kSceneLoaderFile).shadows->scattering, SunScattering{});
  expect_error_scene_loader(R"({"shadows": {"scattering": {"anisotropy": 1}}})", "/shadows/scattering/anisotropy", {"found 1"});
  expect_error_scene_loader(R"({"shadows": {"scattering": {"octaves": 0}}})", "/shadows/scattering/octaves", {"found 0"});
  expect_error_scene_loader(R"({"shadows": {"scattering": {"attenuation": 0}}})", "/shadows/scattering/attenuation", {"(0, 1]"});
  expect_error_scene_loader(R"({"shadows": {"scattering": {"phase": 0.5}}})", "/shadows/scattering/phase", {"unknown key"});
}

TEST(SceneLoader, ShadowsSplatSunlightChoosesWhereTheSplatsAreLit) {
  EXPECT_EQ(parse_scene(R"({"shadows": {}})", kSceneLoaderFile).shadows->splat_sunlight, SplatSunlight::fragments);
  EXPECT_EQ(parse_scene(R"({"shadows": {"splat_sunlight": "vertices"}})", kSceneLoaderFile).shadows->splat_sunlight,
            SplatSunlight::vertices);
  expect_error_scene_loader(R"({"shadows": {"splat_sunlight": "pixels"}})", "/shadows/splat_sunlight",
                            {"fragments", "vertices"});
}

TEST(SceneLoader, LoadsFromFile) {
  TempDir dir;
  const std::string path = dir.write("scene.json", kFullScene);
  const SceneDescription s = load_scene(path);
  EXPECT_EQ(s.file, path);
  EXPECT_EQ(s.name, "fog");
  EXPECT_EQ(s.clouds.size(), 2u);
}

// ---------------------------------------------------------------------------------------------
// The file itself

TEST(SceneLoader, MissingFile) {
  TempDir dir;
  const std::string path = dir.path("no_such_scene.json");
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.place(), "");
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find(std::string("cannot open scene file: ") + std::strerror(ENOENT)),
              std::string::npos)
        << what;
  }
}

TEST(SceneLoader, DirectoryInsteadOfFile) {
  TempDir dir;
  const std::string path = dir.path("a_directory.json");
  std::filesystem::create_directory(path);
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.place(), "");
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("found a folder"), std::string::npos) << what;
  }
}

TEST(SceneLoader, EmptyFile) {
  TempDir dir;
  const std::string path = dir.write("empty.json", "");
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), path);
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("expected a JSON object describing the scene, found an empty file"),
              std::string::npos)
        << what;
  }
  expect_error_scene_loader(" \n\t\n", "", {"found an empty file"});
}

TEST(SceneLoader, TopLevelNotAnObject) {
  expect_error_scene_loader("[1, 2]", "",
               {"expected a JSON object at the top level", "found [1,2] (array of 2)"});
  expect_error_scene_loader("42", "", {"expected a JSON object at the top level", "found 42"});
  expect_error_scene_loader("\"fog\"", "", {"found \"fog\" (string)"});
}

// ---------------------------------------------------------------------------------------------
// JSON syntax

TEST(SceneLoader, SyntaxErrorTrailingCommaLineAndColumn) {
  // The unexpected '}' is the first character of line 4.
  expect_error_scene_loader("{\n  \"name\": \"x\",\n  \"seed\": 3,\n}\n", "line 4, column 1",
               {"invalid JSON", "unexpected '}'", "expected string literal"});
}

TEST(SceneLoader, SyntaxErrorDoubledColonLineAndColumn) {
  // line 3 is `  "seed":: 3`; the second ':' is column 10.
  expect_error_scene_loader("{\n  \"name\": \"x\",\n  \"seed\":: 3\n}", "line 3, column 10",
               {"invalid JSON", "unexpected ':'"});
}

TEST(SceneLoader, SyntaxErrorColumnsCountCharactersNotBytes) {
  // "é" is two bytes but one column: `{"name": "é",,}` has its second ',' at column 14.
  expect_error_scene_loader("{\"name\": \"\xc3\xa9\",,}", "line 1, column 14", {"invalid JSON"});
}

TEST(SceneLoader, SyntaxErrorUnexpectedEndOfInput) {
  // Input ends after column 11 of line 2; the error is one past it.
  expect_error_scene_loader("{\n  \"seed\": 3", "line 2, column 12",
               {"invalid JSON", "unexpected end of input"});
}

TEST(SceneLoader, SyntaxErrorTrailingGarbage) {
  expect_error_scene_loader("{} x", "line 1, column 4", {"invalid JSON", "expected end of input"});
}

TEST(SceneLoader, NumberTooLargeForDouble) {
  expect_error_scene_loader("{\n  \"seed\": 1e400\n}", "line 2, column 15",
               {"expected a number within the range of a double", "found 1e400"});
}

TEST(SceneLoader, DeepNestingRefused) {
  const std::string deep =
      "{\"clouds\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  // The root object and the "clouds" array are two levels; 62 more arrays reach the limit.
  std::string pointer = "/clouds";
  for (int i = 0; i < 62; ++i) pointer += "/0";
  expect_error_scene_loader(deep, pointer, {"expected at most 64 levels of nested arrays and objects"});
}

TEST(SceneLoader, DuplicateKeyRefused) {
  expect_error_scene_loader(R"({"camera": {"near": 1, "near": 2}})", "/camera/near", {"duplicate key \"near\""});
  expect_error_scene_loader(R"({"clouds": [{"count": 1}, {"count": 1, "count": 2}]})", "/clouds/1/count",
               {"duplicate key \"count\""});
}

// ---------------------------------------------------------------------------------------------
// Types

TEST(SceneLoader, StringWhereNumberExpected) {
  expect_error_scene_loader(R"({"clouds": [{"count": 10, "radius": "abc"}]})", "/clouds/0/radius",
               {"expected a number in (0, 1e6], found \"abc\" (string)"});
}

TEST(SceneLoader, NumberWhereObjectExpected) {
  expect_error_scene_loader(R"({"camera": 5})", "/camera", {"expected an object, found 5"});
  expect_error_scene_loader(R"({"output": [800, 600]})", "/output",
               {"expected an object, found [800,600] (array of 2)"});
}

TEST(SceneLoader, WrongContainerTypes) {
  expect_error_scene_loader(R"({"clouds": {"count": 1}})", "/clouds",
               {"expected an array of objects", "(object)"});
  expect_error_scene_loader(R"({"clouds": [3]})", "/clouds/0",
               {"expected an object describing a cloud, found 3"});
  expect_error_scene_loader(R"({"meshes": [null]})", "/meshes/0",
               {"expected an object describing a mesh, found null"});
}

TEST(SceneLoader, WrongScalarTypes) {
  expect_error_scene_loader(R"({"name": 5})", "/name", {"expected a string, found 5"});
  expect_error_scene_loader(R"({"output": {"width": "800"}})", "/output/width",
               {"expected an integer in [1, 8192], found \"800\" (string)"});
  expect_error_scene_loader(R"({"camera": {"near": true}})", "/camera/near",
               {"expected a number in (0, 1e6], found true (boolean)"});
  expect_error_scene_loader(
      R"({"clouds": [{"count": 1, "color": "grey"}]})", "/clouds/0/color",
      {"expected a grey level in [0, 1] or an array of 3 numbers", "found \"grey\" (string)"});
  expect_error_scene_loader(R"({"meshes": [{"type": 1}]})", "/meshes/0/type",
               {"expected a mesh type", "found 1"});
}

// ---------------------------------------------------------------------------------------------
// Ranges

TEST(SceneLoader, NumbersOutOfRange) {
  expect_error_scene_loader(R"({"camera": {"fov_y_deg": 180}})", "/camera/fov_y_deg",
               {"expected a number in (0, 180), found 180"});
  expect_error_scene_loader(R"({"camera": {"near": 0}})", "/camera/near",
               {"expected a number in (0, 1e6], found 0"});
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "density": 1.5}]})", "/clouds/0/density",
               {"expected a number in [0, 1], found 1.5"});
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "jitter": -0.1}]})", "/clouds/0/jitter",
               {"expected a number in [0, 1e6], found -0.1"});
  expect_error_scene_loader(R"({"light": {"color": [1, -1, 1]}})", "/light/color/1",
               {"expected a number in [0, 1e6], found -1"});
  expect_error_scene_loader(R"({"meshes": [{"type": "ground_plane", "color": [0.5, 0.5, 2]}]})",
               "/meshes/0/color/2", {"expected a number in [0, 1], found 2"});
  expect_error_scene_loader(R"({"output": {"fps": 0}})", "/output/fps",
               {"expected a number in (0, 1e6], found 0"});
}

TEST(SceneLoader, AbsurdMagnitudesRefused) {
  // 1e39 overflows a float; it is far outside every range.
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "radius": 1e39}]})", "/clouds/0/radius",
               {"expected a number in (0, 1e6], found 1e+39"});
  expect_error_scene_loader(R"({"camera": {"position": [0, 1e39, 0]}})", "/camera/position/1",
               {"expected a number in [-1e6, 1e6], found 1e+39"});
  // 1e-50 is positive as a double but rounds to 0 as a float.
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "radius": 1e-50}]})", "/clouds/0/radius",
               {"expected a number in (0, 1e6], found 1e-50", "single precision"});
}

TEST(SceneLoader, AClosedRangesEndsAreAcceptedThoughTheyRoundPastItInAFloat) {
  // 0.99 is 0.99000001 in a float, past the anisotropy's closed end 0.99: it reads as the float
  // on the range's side of that end, and so does -0.99.
  for (const char* g : {"0.99", "-0.99"}) {
    const SceneDescription s =
        parse_scene(std::string(R"({"shadows": {"scattering": {"anisotropy": )") + g + "}}}", "lobe.json");
    ASSERT_TRUE(s.shadows.has_value());
    EXPECT_LE(std::abs(s.shadows->scattering.anisotropy), 0.99) << g;
    EXPECT_GT(std::abs(s.shadows->scattering.anisotropy), 0.98999) << g;
  }
  expect_error_scene_loader(R"({"shadows": {"scattering": {"anisotropy": 0.9900001}}})",
                            "/shadows/scattering/anisotropy", {"expected a number in [-0.99, 0.99], found 0.9900001"});
}

TEST(SceneLoader, IntegersOutOfRangeNonIntegralOrNegative) {
  expect_error_scene_loader(R"({"output": {"width": 0}})", "/output/width",
               {"expected an integer in [1, 8192], found 0"});
  expect_error_scene_loader(R"({"output": {"height": 8193}})", "/output/height",
               {"expected an integer in [1, 8192], found 8193"});
  expect_error_scene_loader(R"({"footprint": {"size": 1}})", "/footprint/size",
               {"expected an integer in [2, 4096], found 1"});
  expect_error_scene_loader(R"({"footprint": {"intervals": 100001}})", "/footprint/intervals",
               {"expected an integer in [1, 100000], found 100001"});
  expect_error_scene_loader(R"({"clouds": [{"count": 2.5}]})", "/clouds/0/count",
               {"expected an integer in [1, 10000000], found 2.5", "not a whole number"});
  expect_error_scene_loader(R"({"clouds": [{"count": 10000001}]})", "/clouds/0/count",
               {"expected an integer in [1, 10000000], found 10000001"});
  expect_error_scene_loader(R"({"seed": -1})", "/seed",
               {"expected an integer in [0, 18446744073709551615], found -1"});
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "seed": 1e30}]})", "/clouds/0/seed",
               {"expected an integer in [0, 18446744073709551615], found 1e+30"});
}

TEST(SceneLoader, Vec3MustHaveExactlyThreeNumbers) {
  expect_error_scene_loader(R"({"camera": {"position": [1, 2]}})", "/camera/position",
               {"expected an array of 3 numbers", "found [1,2] (array of 2)"});
  expect_error_scene_loader(R"({"background": [0.1, 0.2, 0.3, 1.0]})", "/background",
               {"expected an array of 3 numbers", "(array of 4)"});
  expect_error_scene_loader(R"({"light": {"direction": 1}})", "/light/direction",
               {"expected an array of 3 numbers", "found 1"});
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "drift": [0, "up", 0]}]})", "/clouds/0/drift/1",
               {"expected a number in [-1e6, 1e6], found \"up\" (string)"});
}

// ---------------------------------------------------------------------------------------------
// Keys

TEST(SceneLoader, UnknownKeyWithSuggestion) {
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "raduis": 0.5}]})", "/clouds/0/raduis",
               {"unknown key \"raduis\"; did you mean \"radius\"?"});
  expect_error_scene_loader(R"({"camrea": {}})", "/camrea",
               {"unknown key \"camrea\"; did you mean \"camera\"?"});
  expect_error_scene_loader(R"({"light": {"colour": [1, 1, 1]}})", "/light/colour", {"did you mean \"color\"?"});
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "box": {"mn": [0, 0, 0]}}]})", "/clouds/0/box/mn",
               {"did you mean \"min\"?"});
  expect_error_scene_loader(
      R"({"output": {"frames_per_second": 30}})", "/output/frames_per_second",
      {"unknown key \"frames_per_second\"; expected one of \"width\", \"height\", \"fps\""});
}

TEST(SceneLoader, UnknownKeyWithoutSuggestionListsKnownKeys) {
  expect_error_scene_loader(R"({"frobnicate": 1})", "/frobnicate",
               {"unknown key \"frobnicate\"; expected one of \"name\", \"seed\", \"output\", "
                "\"background\", "
                "\"camera\", \"light\", \"footprint\", \"render\", \"clouds\", \"meshes\""});
}

TEST(SceneLoader, UnknownKeyPointerIsEscaped) {
  expect_error_scene_loader(R"({"a/b~c": 1})", "/a~1b~0c", {"unknown key \"a/b~c\""});
}

TEST(SceneLoader, MissingRequiredKeys) {
  expect_error_scene_loader(R"({"clouds": [{"count": 1}, {"radius": 1}]})", "/clouds/1",
               {"missing required key \"count\"",
                "expected the number of particles, an integer in [1, 10000000]"});
  expect_error_scene_loader(R"({"meshes": [{"scale": 2}]})", "/meshes/0",
               {"missing required key \"type\"", "\"ground_plane\", \"water_tower\""});
}

TEST(SceneLoader, UnknownMeshType) {
  expect_error_scene_loader(R"({"meshes": [{"type": "ground_plane"}, {"type": "tower"}]})", "/meshes/1/type",
               {"unknown mesh type \"tower\"; expected one of \"ground_plane\", \"water_tower\""});
  expect_error_scene_loader(R"({"meshes": [{"type": "water_towr"}]})", "/meshes/0/type",
               {"unknown mesh type \"water_towr\"", "did you mean \"water_tower\"?"});
}

// ---------------------------------------------------------------------------------------------
// Checks across fields

TEST(SceneLoader, NearMustBeLessThanFar) {
  expect_error_scene_loader(R"({"camera": {"near": 5, "far": 5}})", "/camera/far",
               {"expected \"far\" greater than \"near\" (5), found 5"});
  // far left at its default (200) is still checked against a larger near.
  expect_error_scene_loader(R"({"camera": {"near": 300}})", "/camera/far",
               {"greater than \"near\" (300), found 200"});
}

TEST(SceneLoader, BoxMinMustBeBelowMaxOnEveryAxis) {
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "box": {"min": [0, 4, 0], "max": [1, 1, 1]}}]})",
               "/clouds/0/box",
               {"expected \"min\" < \"max\" on every axis", "min.y = 4 >= max.y = 1"});
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "box": {"min": [2, 0, 0], "max": [2, 1, 1]}}]})",
               "/clouds/0/box", {"min.x = 2 >= max.x = 2"});
  // Only min given: checked against the default max (4, 4, 4).
  expect_error_scene_loader(R"({"clouds": [{"count": 1, "box": {"min": [0, 0, 5]}}]})", "/clouds/0/box",
               {"min.z = 5 >= max.z = 4"});
}

TEST(SceneLoader, LightDirectionMustBeNonZero) {
  expect_error_scene_loader(R"({"light": {"direction": [0, 0, 0]}})", "/light/direction",
               {"expected a non-zero light direction", "found [0, 0, 0]"});
}

TEST(SceneLoader, UpMustBeNonZeroAndNotParallelToView) {
  expect_error_scene_loader(R"({"camera": {"up": [0, 0, 0]}})", "/camera/up", {"expected a non-zero up vector"});
  expect_error_scene_loader(
      R"({"camera": {"position": [0, 10, 0], "target": [0, 0, 0]}})", "/camera/up",
      {"expected an up vector not parallel to the view direction [0, -10, 0]", "found [0, 1, 0]"});
  // Anti-parallel counts too.
  expect_error_scene_loader(R"({"camera": {"position": [0, 0, 0], "target": [0, 0, -1], "up": [0, 0, 2]}})",
               "/camera/up", {"not parallel to the view direction"});
}

TEST(SceneLoader, CameraPositionMustDifferFromTarget) {
  expect_error_scene_loader(R"({"camera": {"position": [1, 2, 3], "target": [1, 2, 3]}})", "/camera/target",
               {"expected a target different from the camera position [1, 2, 3], found [1, 2, 3]"});
}

}  // namespace
}  // namespace pyro

namespace pyro {
namespace {

TEST(SceneLoader, RenderAndStereoSettings) {
  const SceneDescription s = parse_scene(
      R"({"render": {"billboards": "viewpoint", "layer_scale": 0.25},
          "camera": {"stereo": {"interocular": 0.3, "zero_parallax_distance": 6}}})", "r.json");
  EXPECT_EQ(s.render.billboards, BillboardAlignment::viewpoint);
  EXPECT_FLOAT_EQ(s.render.layer_scale, 0.25f);
  EXPECT_FLOAT_EQ(s.camera.interocular, 0.3f);
  EXPECT_FLOAT_EQ(s.camera.zero_parallax_distance, 6.0f);
  EXPECT_FALSE(s.camera.swap_eyes);
  EXPECT_TRUE(parse_scene(R"({"camera": {"stereo": {"eye_order": "right-left"}}})", "r.json").camera.swap_eyes);
  expect_error_scene_loader(R"({"camera": {"stereo": {"eye_order": "left"}}})", "/camera/stereo/eye_order",
               {"expected one of \"left-right\", \"right-left\""});
  expect_error_scene_loader(R"({"render": {"billboards": "viewpiont"}})", "/render/billboards",
               {"unknown value \"viewpiont\"", "did you mean \"viewpoint\""});
  expect_error_scene_loader(R"({"render": {"layer_scale": 0.3}})", "/render/layer_scale",
               {"expected one of 1, 0.5, 0.25, 0.125"});
  expect_error_scene_loader(R"({"camera": {"stereo": {"interocular": -1}}})", "/camera/stereo/interocular",
               {"expected a number in"});
}

TEST(SceneLoader, FireBlackbodyTableKeys) {
  // Defaults: the paper's 2500-3200 K (components/explosion_shading.h's).
  const SceneDescription d = parse_scene("{}", "r.json");
  EXPECT_FLOAT_EQ(d.render.fire_t_min, 2500.0f);
  EXPECT_FLOAT_EQ(d.render.fire_t_max, 3200.0f);
  EXPECT_FLOAT_EQ(d.render.fire_emission, 6.0f);
  EXPECT_FLOAT_EQ(d.render.fire_detail_range, 500.0f);
  const SceneDescription s = parse_scene(
      R"({"render": {"fire": {"t_min": 1000, "t_max": 3300, "emission": 9, "detail_range": 250}}})",
      "r.json");
  EXPECT_FLOAT_EQ(s.render.fire_t_min, 1000.0f);
  EXPECT_FLOAT_EQ(s.render.fire_t_max, 3300.0f);
  EXPECT_FLOAT_EQ(s.render.fire_emission, 9.0f);
  EXPECT_FLOAT_EQ(s.render.fire_detail_range, 250.0f);
  expect_error_scene_loader(R"({"render": {"fire": {"t_min": 3500}}})", "/render/fire/t_max",
               {"expected \"t_max\" greater than \"t_min\" (3500 K), found 3200"});
  expect_error_scene_loader(R"({"render": {"fire": {"t_min": 0}}})", "/render/fire/t_min", {"expected a number in"});
  expect_error_scene_loader(R"({"render": {"fire": {"emission": -1}}})", "/render/fire/emission",
               {"expected a number in"});
  expect_error_scene_loader(R"({"render": {"fire": {"t_mn": 1000}}})", "/render/fire/t_mn", {"did you mean \"t_min\""});
}

}  // namespace
}  // namespace pyro
