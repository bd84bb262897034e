// Quality from an error target end to end, on a small cheap Gaussian scene:
// `pyro render` of a scene with quality.max_rmse picks settings whose frame, as written to PNG,
// is within the target of the CPU reference computed here (render_particles_reference over the
// scene's background: an independent path); the pick is cached and reused without measuring,
// and measured again when the scene changes; bad values exit 2 naming the JSON pointer.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "components/particle_set.h"
#include "components/view.h"
#include "engine/io/png_file.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/math/color.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "tests/support/file_bytes.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kTarget = 0.03;

// 64x48, 60 Gaussian particles, no meshes (so the reference needs no opaque scene).
std::string tiny_scene(const std::string& extra_quality = "\"quality\": {\"max_rmse\": 0.03}",
                       int seed = 7) {
  return "{\"name\": \"tiny fog\", \"seed\": " + std::to_string(seed) +
         ", \"output\": {\"width\": 64, \"height\": 48, \"fps\": 30},"
         " \"background\": [0.5, 0.55, 0.6],"
         " \"camera\": {\"position\": [0, 1.5, 8], \"target\": [0, 1.5, 0], \"fov_y_deg\": 45},"
         " \"clouds\": [{\"count\": 60, \"radius\": 0.6, \"density\": 0.3, \"color\": 0.85,"
         " \"box\": {\"min\": [-2, 0.5, -2], \"max\": [2, 2.5, 2]}, \"drift\": [0.1, 0, 0]}]" +
         (extra_quality.empty() ? std::string() : ", " + extra_quality) + "}";
}

void write_pyro_cli_quality(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
}

// Points the quality cache at a scratch folder for this test (restored after).
class CacheDir {
 public:
  explicit CacheDir(const fs::path& dir) {
    if (const char* old = std::getenv("PYRO_CACHE_DIR")) saved_ = old, had_ = true;
    setenv("PYRO_CACHE_DIR", dir.c_str(), 1);
  }
  ~CacheDir() {
    if (had_) setenv("PYRO_CACHE_DIR", saved_.c_str(), 1);
    else unsetenv("PYRO_CACHE_DIR");
  }

 private:
  std::string saved_;
  bool had_ = false;
};

TEST(PyroCliQuality, RenderedPickMeetsTheTargetAgainstTheCpuReference) {
  const fs::path dir = test::scratch_dir("quality_render");
  const CacheDir cache(dir / "cache");
  const fs::path scene_file = dir / "tiny.json";
  write_pyro_cli_quality(scene_file, tiny_scene());
  const auto r = test::run_pyro({"render", scene_file.string(), "--out", (dir / "out").string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("pyro: quality: max RMSE 0.03 -> layer scale"), std::string::npos) << r.err;
  const json summary = test::last_json_line(r.out);
  ASSERT_TRUE(summary.contains("quality")) << summary.dump();
  const json& q = summary["quality"];
  EXPECT_TRUE(q["met"].get<bool>());
  EXPECT_LE(q["expected_rmse"].get<double>(), kTarget);
  EXPECT_EQ(summary["layer_scale"], q["settings"]["layer_scale"]);

  // The reference, independently: the particles at frame 0 and the camera, integrated exactly.
  const SceneDescription scene = load_scene(scene_file.string());
  RuntimeOptions o;
  o.readback = false;
  SceneRuntime runtime(scene, o);
  runtime.step();
  const CameraFrame camera = runtime.world().resource<View>().eyes.at(0);
  const ParticlePool all = gather_particles(runtime.world());
  ASSERT_EQ(all.size(), 60u);
  const RgbImage reference = render_particles_reference(all, camera, glm::dvec3(scene.background));
  const PngImage png = read_png((dir / "out" / "frame_0000.png").string());
  ASSERT_EQ(png.width, reference.width);
  ASSERT_EQ(png.height, reference.height);
  RgbImage rendered = reference;
  for (size_t i = 0, n = size_t(png.width) * png.height; i < n; ++i)
    for (size_t ch = 0; ch < 3; ++ch)
      rendered.rgb[3 * i + ch] = srgb_to_linear(png.pixels[i * png.channels + ch] / 255.0f);
  const double rmse = image_rmse(rendered, reference);
  EXPECT_LE(rmse, kTarget) << "picked " << q["settings"].dump();
  EXPECT_GT(rmse, 0.0);
}

TEST(PyroCliQuality, PickIsCachedAndMeasuredAgainWhenTheSceneChanges) {
  const fs::path dir = test::scratch_dir("quality_cache");
  const CacheDir cache(dir / "cache");
  const fs::path scene_file = dir / "tiny.json";
  write_pyro_cli_quality(scene_file, tiny_scene());
  const std::vector<std::string> args = {"quality", scene_file.string(), "--no-verify", "--json"};

  const auto first = test::run_pyro(args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const json a = test::last_json_line(first.out);
  EXPECT_FALSE(a["from_cache"].get<bool>());
  EXPECT_EQ(a["measured_candidates"], 12);
  EXPECT_NE(first.err.find("measuring"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "cache" / "quality.json"));

  const auto second = test::run_pyro(args);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const json b = test::last_json_line(second.out);
  EXPECT_TRUE(b["from_cache"].get<bool>());
  EXPECT_EQ(b["measured_candidates"], 0);
  EXPECT_EQ(second.err.find("measuring"), std::string::npos) << second.err;
  EXPECT_EQ(b["settings"], a["settings"]);
  EXPECT_EQ(b["expected_rmse"], a["expected_rmse"]);
  EXPECT_EQ(b["cache_key"], a["cache_key"]);

  write_pyro_cli_quality(scene_file, tiny_scene("\"quality\": {\"max_rmse\": 0.03}", 8));  // another seed
  const auto third = test::run_pyro(args);
  ASSERT_EQ(third.exit_code, 0) << third.err;
  const json c = test::last_json_line(third.out);
  EXPECT_FALSE(c["from_cache"].get<bool>());
  EXPECT_EQ(c["measured_candidates"], 12);
  EXPECT_NE(c["cache_key"], a["cache_key"]);
}

// The cache is an input like any other: an entry whose pick is none of the scene's candidates
// (a footprint of 0 or 1e9 would reach the renderer) or a cache that is not a file is discarded
// with a note, and the pick measured again.
TEST(PyroCliQuality, ADamagedCacheIsDiscardedWithANote) {
  const fs::path dir = test::scratch_dir("quality_damaged_cache");
  const CacheDir cache(dir / "cache");
  const fs::path scene_file = dir / "tiny.json";
  write_pyro_cli_quality(scene_file, tiny_scene());
  const std::vector<std::string> args = {"render", scene_file.string(), "--out", (dir / "out").string(), "--json"};
  ASSERT_EQ(test::run_pyro(args).exit_code, 0);
  const fs::path cache_file = dir / "cache" / "quality.json";
  for (const double footprint : {1e9, 0.0}) {
    json all = json::parse(test::read_bytes(cache_file));
    ASSERT_EQ(all.size(), 1u);
    for (auto& [key, entry] : all.items()) entry["settings"]["footprint_size"] = footprint;
    write_pyro_cli_quality(cache_file, all.dump());
    fs::remove_all(dir / "out");
    const auto r = test::run_pyro(args);
    ASSERT_EQ(r.exit_code, 0) << footprint << ": " << r.err;
    EXPECT_NE(r.err.find("discarded a damaged entry"), std::string::npos) << r.err;
    EXPECT_FALSE(test::last_json_line(r.out)["quality"]["from_cache"].get<bool>());
  }
  // A folder where the cache file should be: ignored, and the render still succeeds.
  fs::remove(cache_file);
  fs::create_directories(cache_file);
  fs::remove_all(dir / "out");
  const auto r = test::run_pyro(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("ignored the cache"), std::string::npos) << r.err;
}

// A pick is part of the run: every range of one output folder draws with the pick recorded in
// its manifest, whatever the cache says (or when there is none to write).
TEST(PyroCliQuality, EveryRangeOfARunUsesThePickRecordedWithIt) {
  const fs::path dir = test::scratch_dir("quality_recorded_pick");
  const CacheDir cache(dir / "not_writable" / "quality.json" / "cache");  // under a file: no cache
  fs::create_directories(dir / "not_writable");
  write_pyro_cli_quality(dir / "not_writable" / "quality.json", "a file, so no cache folder can be made under it");
  const fs::path scene_file = dir / "tiny.json", out = dir / "out";
  write_pyro_cli_quality(scene_file, tiny_scene());
  auto range = [&](const std::string& frames) {
    return test::run_pyro({"render", scene_file.string(), "--out", out.string(), "--frames", frames, "--json"});
  };
  const auto first = range("0:0");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  // Another valid candidate recorded in the manifest: the next range must take it, not measure.
  json manifest = json::parse(test::read_bytes(out / ".pyro_manifest.json"));
  json& settings = manifest["choices"]["quality"]["settings"];
  const int other_footprint = settings["footprint_size"].get<int>() == 16 ? 32 : 16;
  settings["footprint_size"] = other_footprint;
  write_pyro_cli_quality(out / ".pyro_manifest.json", manifest.dump());
  const auto second = range("1:1");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(second.err.find("measuring"), std::string::npos) << second.err;
  EXPECT_EQ(test::last_json_line(second.out)["quality"]["settings"]["footprint_size"], other_footprint);
}

TEST(PyroCliQuality, BadTargetsExitTwoNamingThePointer) {
  const fs::path dir = test::scratch_dir("quality_bad");
  const CacheDir cache(dir / "cache");
  const struct {
    std::string quality, pointer;
  } cases[] = {
      {"\"quality\": {\"max_rmse\": 0}", "/quality/max_rmse"},
      {"\"quality\": {\"max_rmse\": 1.5}", "/quality/max_rmse"},
      {"\"quality\": {\"max_rmse\": \"low\"}", "/quality/max_rmse"},
      {"\"quality\": {}", "at /quality: missing required key \"max_rmse\""},
      {"\"quality\": {\"max_rmse\": 0.02, \"max_rsme\": 1}", "/quality/max_rsme"},
      {"\"quality\": 0.02", "at /quality: expected an object"},
  };
  for (const auto& c : cases) {
    const fs::path scene_file = dir / "bad.json";
    write_pyro_cli_quality(scene_file, tiny_scene(c.quality));
    const fs::path out = dir / "out";
    const auto r = test::run_pyro({"render", scene_file.string(), "--out", out.string()});
    EXPECT_EQ(r.exit_code, 2) << c.quality << "\n" << r.err;
    EXPECT_NE(r.err.find(c.pointer), std::string::npos) << c.quality << "\n" << r.err;
    EXPECT_NE(r.err.find(scene_file.string()), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir / "cache"));
  }
  // pyro quality without any target names the key it needs.
  const fs::path plain = dir / "plain.json";
  write_pyro_cli_quality(plain, tiny_scene(""));
  const auto r = test::run_pyro({"quality", plain.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/quality/max_rmse"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace pyro
