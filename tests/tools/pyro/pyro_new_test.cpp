// `pyro new FILE --template NAME`: every template, written into a scratch folder, names a schema
// that resolves from there, passes the loader and the independent schema validator, and renders
// a frame that is not blank; the smoke template's plume rises above its chimney top; and the
// command refuses what it must without writing anything.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "components/emitter.h"
#include "components/particle_set.h"
#include "engine/core/content_path.h"
#include "engine/io/png_file.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/file_bytes.h"
#include "tests/support/schema_validator.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const std::vector<std::string> kNewTemplateNames = {"campfire", "clouds", "explosion", "fog", "smoke", "vdb"};

// The fraction of pixels further than 8 levels (any channel) from the background's own pixel.
double fraction_unlike_background(const PngImage& image, const json& background) {
  const std::vector<float> rgba = {background[0].get<float>(), background[1].get<float>(),
                                   background[2].get<float>(), 1.0f};
  const std::vector<uint8_t> bg = linear_rgba_to_srgb8(rgba, 1, 1);
  std::size_t unlike = 0;
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(image.pixels[i * image.channels + c]) - int(bg[c])) > 8) {
        ++unlike;
        break;
      }
  return static_cast<double>(unlike) / static_cast<double>(pixels);
}

TEST(PyroNew, ListsEveryTemplateWithItsDescription) {
  const auto r = test::run_pyro({"new", "--list"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& name : kNewTemplateNames)
    EXPECT_NE(("\n" + r.out).find("\n" + name + " "), std::string::npos) << name << " in:\n" << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), static_cast<long>(kNewTemplateNames.size())) << r.out;
}

// Written two folders below a scratch folder, far from content/: the schema and the VDB
// template's volume file must still resolve from the written file's folder.
TEST(PyroNew, EveryTemplateLoadsValidatesAndRendersWhereItIsWritten) {
  const fs::path folder = test::scratch_dir("pyro_new_templates") / "a" / "b";
  fs::create_directories(folder);
  const fs::path schema = fs::path(content_dir()) / "scene.schema.json";
  std::vector<fs::path> files;
  for (const std::string& name : kNewTemplateNames) {
    const fs::path file = folder / (name + ".json");
    const auto r = test::run_pyro({"new", file.string(), "--template", name});
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const json scene = json::parse(test::read_bytes(file));
    EXPECT_TRUE(fs::equivalent(folder / scene.at("$schema").get<std::string>(), schema)) << name;
    EXPECT_NO_THROW(load_scene(file.string())) << name;
    files.push_back(file);
  }
  const json vdb = json::parse(test::read_bytes(folder / "vdb.json"));
  EXPECT_TRUE(fs::equivalent(folder / vdb["volumes"][0]["file"].get<std::string>(),
                             fs::path(content_dir()) / "volumes" / "sample_cloud.vdb"));
  const std::vector<std::string> verdicts = test::jsonschema_verdicts(schema, files);
  ASSERT_EQ(verdicts.size(), files.size()) << "is python3-jsonschema installed?";
  for (std::size_t i = 0; i < files.size(); ++i) {
    EXPECT_EQ(verdicts[i], "valid") << files[i];
    const fs::path out = folder / ("frames_" + kNewTemplateNames[i]);
    const auto r = test::run_pyro({"render", files[i].string(), "--out", out.string(), "--frames", "1",
                                   "--width", "64", "--height", "48"});
    ASSERT_EQ(r.exit_code, 0) << files[i] << ": " << r.err;
    const PngImage image = read_png((out / "frame_0000.png").string());
    ASSERT_EQ(image.width, 64);
    const json background = json::parse(test::read_bytes(files[i])).at("background");
    EXPECT_GT(fraction_unlike_background(image, background), 0.05) << files[i];
  }
}

// Mean height of every emitted particle of the runtime.
double mean_particle_height(SceneRuntime& runtime, float& lowest) {
  double sum = 0.0;
  std::size_t count = 0;
  lowest = 1e9f;
  runtime.world().each<Emitter, ParticleSet>([&](Emitter&, ParticleSet& set) {
    for (std::size_t i = 0; i < set.pool.size(); ++i) {
      sum += set.pool.py[i];
      lowest = std::min(lowest, set.pool.py[i]);
    }
    count += set.pool.size();
  });
  return count == 0 ? 0.0 : sum / static_cast<double>(count);
}

// The emitter sits on the top of a chimney primitive (a cylinder standing on the ground whose
// top disc holds the emitter's disc); the plume rises out of it (y = 3): nothing sinks below it,
// and its mean height grows over the first frames (the prewarm is shorter than the lifetime).
TEST(PyroNew, TheSmokeTemplatesPlumeRisesFromTheChimneyTop) {
  const fs::path file = test::scratch_dir("pyro_new_smoke") / "smoke.json";
  ASSERT_EQ(test::run_pyro({"new", file.string(), "--template", "smoke"}).exit_code, 0);
  const SceneDescription scene = load_scene(file.string());
  const auto chimney = std::find_if(scene.meshes.begin(), scene.meshes.end(),
                                    [](const MeshDescription& m) { return m.kind == MeshKind::cylinder; });
  ASSERT_NE(chimney, scene.meshes.end()) << "the smoke template has no chimney";
  const nlohmann::json emitter_shape = nlohmann::json::parse(test::read_bytes(file))["emitters"][0]["shape"];
  const std::vector<float> at = emitter_shape["position"].get<std::vector<float>>();
  EXPECT_FLOAT_EQ(chimney->position.y, 0.0f);  // standing on the ground
  EXPECT_NEAR(chimney->position.y + chimney->height * chimney->scale, at[1], 1e-5f);
  EXPECT_NEAR(std::hypot(chimney->position.x - at[0], chimney->position.z - at[2]) +
                  emitter_shape["radius"].get<float>(),
              0.0f, chimney->radius * chimney->scale);
  OpenSceneOptions options;
  options.runtime.readback = false;
  OpenedScene opened = open_scene(file.string(), options);
  float lowest = 0.0f;
  const double at_start = mean_particle_height(*opened.runtime, lowest);
  EXPECT_GT(at_start, 3.5);
  EXPECT_GT(lowest, 2.8f);
  double previous = at_start;
  for (int step = 1; step <= 30; ++step) {
    opened.runtime->simulate_step();
    if (step % 10 != 0) continue;
    const double mean = mean_particle_height(*opened.runtime, lowest);
    EXPECT_GT(mean, previous + 0.05) << "after " << step << " steps";
    EXPECT_GT(lowest, 2.8f) << "after " << step << " steps";
    previous = mean;
  }
}

// The explosion's fireball and smoke fall back under gravity as the shipped explosion's do
// (their dynamics name gravity_scale 1 against the rising defaults): after 40 frames the mean
// particle is below y = 4, near the view's centre (the camera looks at y = 3 from 15 units away
// with a 50 degree field), not up at the frame's top edge near y = 10 where rising smoke is.
TEST(PyroNew, TheExplosionTemplatesBurstStaysInView) {
  const fs::path file = test::scratch_dir("pyro_new_explosion") / "explosion.json";
  ASSERT_EQ(test::run_pyro({"new", file.string(), "--template", "explosion"}).exit_code, 0);
  OpenSceneOptions options;
  options.runtime.readback = false;
  OpenedScene opened = open_scene(file.string(), options);
  for (int step = 0; step < 40; ++step) opened.runtime->simulate_step();
  float lowest = 0.0f;
  const double mean = mean_particle_height(*opened.runtime, lowest);
  std::printf("explosion template after 40 frames: mean particle height %.2f\n", mean);
  EXPECT_LT(mean, 4.0);
}

TEST(PyroNew, RefusesAnExistingFileAnUnknownTemplateAndAMissingFolderWritingNothing) {
  const fs::path folder = test::scratch_dir("pyro_new_refusals");
  const fs::path existing = folder / "mine.json";
  std::ofstream(existing) << "keep";
  auto r = test::run_pyro({"new", existing.string(), "--template", "fog"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a file exists there already; pass --force"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_bytes(existing), "keep");

  r = test::run_pyro({"new", (folder / "other.json").string(), "--template", "clods"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown template \"clods\"; expected one of \"campfire\", \"clouds\""), std::string::npos)
      << r.err;

  r = test::run_pyro({"new", (folder / "no_such_folder" / "a.json").string(), "--template", "fog"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("there is no folder"), std::string::npos) << r.err;

  r = test::run_pyro({"new", folder.string(), "--template", "fog", "--force"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("found a folder"), std::string::npos) << r.err;

  std::vector<std::string> entries;
  for (const auto& e : fs::directory_iterator(folder)) entries.push_back(e.path().filename().string());
  EXPECT_EQ(entries, std::vector<std::string>{"mine.json"});

  r = test::run_pyro({"new", existing.string(), "--template", "fog", "--force"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json::parse(test::read_bytes(existing)).at("clouds").size(), 1u);
}

}  // namespace
}  // namespace pyro
