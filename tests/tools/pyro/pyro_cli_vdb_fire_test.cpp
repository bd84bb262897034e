// pyro import-vdb with a temperature grid, end to end: a Blender/Mantaflow-like smoke cache frame
// written here with OpenVDB (density, normalised temperature, velocity) imports as fire and smoke
// with the defaults and meets its error target with the emission measured; a kelvin grid is taken
// as kelvin; named grids are refused clearly. The OpenUSD densityAndHeat file (shared data,
// skipped when absent) imports its "heat" grid, meets the target, and renders with the table's
// black-body chromaticity in its hottest region and redder where it is cooler.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>


#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "engine/math/blackbody.h"
#include "engine/math/temperature_emission.h"
#include "engine/volume/procedural_fire.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::string write_cache(const fs::path& dir, bool kelvin) {
  ProceduralFireOptions o;
  o.width = 16;
  o.kelvin = kelvin;
  const std::string path = (dir / (kelvin ? "kelvin.vdb" : "fluid_data_0042.vdb")).string();
  write_vdb_grids(path, make_procedural_fire(o));
  return path;
}

nlohmann::json import(const std::string& vdb, const std::string& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args{"import-vdb", vdb, "--out", out, "--json", "--width", "96", "--height", "96"};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CommandResult r = test::run_pyro(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::printf("%s", r.err.c_str());
  return r.exit_code == 0 ? test::last_json_line(r.out) : nlohmann::json::object();
}

// The frame of a scene drawing `pyrop` unlit over black, with the default emission or dark.
RgbImage fire_frame(const fs::path& dir, const std::string& pyrop, bool glowing) {
  const std::string path = (dir / (glowing ? "fire.json" : "dark.json")).string();
  std::ofstream(path) << R"({"output": {"width": 128, "height": 128}, "background": [0, 0, 0],
      "camera": {"position": [0, 0, 12], "target": [0, 0, 0], "fov_y_deg": 40, "near": 0.5, "far": 100},
      "volumes": [{"file": ")" << pyrop << R"(", "size": 6)" << (glowing ? "" : R"(, "emission": {"intensity": 0})")
                      << "}]}";
  RuntimeOptions o;
  o.readback = true;
  SceneRuntime runtime(load_scene(path), o);
  runtime.draw_frame(0);
  return rgb_of(runtime.image());
}

// The emitted light alone: the frame with the default emission minus the frame at intensity 0 (the
// compositing is linear in the particles' radiance at fixed opacities).
std::vector<glm::dvec3> emitted_light(const fs::path& dir, const std::string& pyrop) {
  const RgbImage hot = fire_frame(dir, pyrop, true), dark = fire_frame(dir, pyrop, false);
  std::vector<glm::dvec3> out;
  for (int y = 0; y < hot.height; ++y)
    for (int x = 0; x < hot.width; ++x)
      out.emplace_back(hot.at(x, y)[0] - dark.at(x, y)[0], hot.at(x, y)[1] - dark.at(x, y)[1],
                       hot.at(x, y)[2] - dark.at(x, y)[2]);
  return out;
}

double luminance_pyro_cli_vdb_fire(const glm::dvec3& rgb) { return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z; }

TEST(PyroImportVdbFire, AMantaflowCacheFrameImportsAsFireAndSmokeWithTheDefaults) {
  const fs::path dir = test::scratch_dir("cli_vdb_fire_mantaflow");
  const std::string vdb = write_cache(dir, false), out = (dir / "fire.pyrop").string();
  const nlohmann::json s = import(vdb, out);
  ASSERT_TRUE(s.contains("temperature"));
  EXPECT_EQ(s["temperature"]["grid"], "temperature");
  EXPECT_EQ(s["temperature"]["mapping"], "normalised");
  // Normalised heat in [0, 1] onto [1000, 2500] K: the hottest value's kelvin in closed form.
  const double top = s["temperature"]["max"].get<double>();
  ASSERT_GT(top, 0.5);
  ASSERT_LE(top, 1.0);
  EXPECT_NEAR(s["temperature"]["hottest_kelvin"].get<double>(), kGlowKelvin + (kFlameKelvin - kGlowKelvin) * top, 1e-3);
  EXPECT_TRUE(s["target_met"].get<bool>()) << s.dump();
  const ParticleFile file = read_particle_file(out);
  ASSERT_EQ(file.temperature.size(), file.anisotropic.size());
  // Fire and smoke: the brightest emitted pixel is a flame colour (red over green over blue).
  const std::vector<glm::dvec3> light = emitted_light(dir, out);
  const auto hottest = std::max_element(light.begin(), light.end(),
                                        [](const glm::dvec3& a, const glm::dvec3& b) { return luminance_pyro_cli_vdb_fire(a) < luminance_pyro_cli_vdb_fire(b); });
  EXPECT_GT(luminance_pyro_cli_vdb_fire(*hottest), 0.05);
  EXPECT_GT(hottest->x, hottest->y);
  EXPECT_GT(hottest->y, hottest->z);
}

TEST(PyroImportVdbFire, KelvinGridsAreKelvinAndTheGridCanBeTurnedOff) {
  const fs::path dir = test::scratch_dir("cli_vdb_fire_kelvin");
  const std::string vdb = write_cache(dir, true);
  const nlohmann::json s = import(vdb, (dir / "k.pyrop").string(), {"--error", "0.05"});
  EXPECT_EQ(s["temperature"]["mapping"], "kelvin");
  EXPECT_DOUBLE_EQ(s["temperature"]["scale"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(s["temperature"]["offset"].get<double>(), 0.0);
  const nlohmann::json off = import(vdb, (dir / "off.pyrop").string(), {"--error", "0.05", "--temperature-grid", "none"});
  EXPECT_TRUE(off["temperature"].is_null());
  EXPECT_TRUE(read_particle_file((dir / "off.pyrop").string()).temperature.empty());
}

TEST(PyroImportVdbFire, NamedGridsThatAreAbsentOrNotFloatAreRefused) {
  const fs::path dir = test::scratch_dir("cli_vdb_fire_refused");
  const std::string vdb = write_cache(dir, false), out = (dir / "x.pyrop").string();
  for (const std::string grid : {"fuel", "velocity"}) {
    const test::CommandResult r = test::run_pyro({"import-vdb", vdb, "--out", out, "--temperature-grid", grid});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(vdb), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--temperature-grid"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\"temperature\" float"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// The Cycles fire comparison needs a fire: a file without a temperature grid is refused by name.
TEST(PyroImportVdbFire, TheCyclesFireBenchRefusesAFileWithoutFire) {
  const std::string cloud = content_path("volumes/sample_cloud.vdb");
  const test::CommandResult r =
      test::run_pyro({"bench", "cycles-fire", cloud, "--width", "8", "--height", "8", "--blender", "/bin/false"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(cloud), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a VDB file with a temperature grid"), std::string::npos) << r.err;
}

// A .vdb named in a scene is imported on load as isotropic particles whose colours carry their
// fire: an unlit scene glows; a lit one is refused by name (the albedo would replace the fire).
TEST(PyroImportVdbFire, AVdbSceneGlowsOnLoadAndALitOneIsRefused) {
  const fs::path dir = test::scratch_dir("cli_vdb_fire_on_load");
  const std::string vdb = write_cache(dir, false);
  const RgbImage hot = fire_frame(dir, vdb, true), dark = fire_frame(dir, vdb, false);
  EXPECT_GT(image_rmse(hot, dark), 0.004);
  const std::string lit = (dir / "lit.json").string();
  std::ofstream(lit) << R"({"shadows": {}, "volumes": [{"file": ")" << vdb << R"("}]})";
  try {
    RuntimeOptions o;
    SceneRuntime runtime(load_scene(lit), o);
    ADD_FAILURE() << "a lit scene with an isotropic fire was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), lit);
    EXPECT_EQ(e.place(), "/volumes/0/emission");
  }
  const std::string off = (dir / "lit_off.json").string();
  std::ofstream(off) << R"({"shadows": {}, "volumes": [{"file": ")" << vdb << R"(", "temperature_grid": "none"}]})";
  EXPECT_NO_THROW(SceneRuntime(load_scene(off), RuntimeOptions{}));
}

TEST(PyroImportVdbFire, OpenUsdDensityAndHeatGlowsWithTheTablesChromaticity) {
  const fs::path shared = fs::path(PYRO_SHARED_DATA_DIR) / "vdb" / "openusd_densityAndHeat.vdb";
  if (!fs::exists(shared)) GTEST_SKIP() << "no third-party VDB file at " << shared.string() << " (optional data)";
  const fs::path dir = test::scratch_dir("cli_vdb_fire_openusd");
  const std::string out = (dir / "heat.pyrop").string();
  const nlohmann::json s = import(shared.string(), out);
  EXPECT_EQ(s["temperature"]["grid"], "heat");
  EXPECT_TRUE(s["target_met"].get<bool>()) << "the error target with emission: " << s.dump();
  // The hottest particle's temperature, through the map the import recorded.
  const ParticleFile file = read_particle_file(out);
  const TemperatureMapping map = [&] {
    TemperatureMapping m;
    m.scale = s["temperature"]["scale"].get<double>();
    m.offset = s["temperature"]["offset"].get<double>();
    return m;
  }();
  double hottest_kelvin = 0.0;
  for (float t : file.temperature) hottest_kelvin = std::max(hottest_kelvin, map.kelvin(t));
  const std::vector<glm::dvec3> light = emitted_light(dir, out);
  std::vector<glm::dvec3> emitting;
  for (const glm::dvec3& l : light)
    if (luminance_pyro_cli_vdb_fire(l) > 0.0) emitting.push_back(l);
  ASSERT_GT(emitting.size(), 50u);
  std::sort(emitting.begin(), emitting.end(), [](const glm::dvec3& a, const glm::dvec3& b) { return luminance_pyro_cli_vdb_fire(a) > luminance_pyro_cli_vdb_fire(b); });
  // The hottest region: the brightest 1 % of the emitting pixels.
  glm::dvec3 hot(0.0);
  const size_t top = std::max<size_t>(1, emitting.size() / 100);
  for (size_t i = 0; i < top; ++i) hot += emitting[i];
  const BlackbodyTable table = make_blackbody_table(kGlowKelvin, hottest_kelvin, 256);
  const glm::dvec2 want = linear_srgb_chromaticity(glm::dvec3(sample_blackbody_rgb(table, hottest_kelvin)));
  const glm::dvec2 got = linear_srgb_chromaticity(hot);
  std::printf("hottest particle %.0f K: table xy (%.4f, %.4f), hottest region xy (%.4f, %.4f)\n", hottest_kelvin,
              want.x, want.y, got.x, got.y);
  EXPECT_LT(glm::length(got - want), 0.01);
  // The coolest emitting region against the hottest: the light emitted by the coolest third of the
  // particles that glow (at least 1 % of the hottest's luminance) and by the hottest third, each
  // rendered through the whole medium (the others' temperatures set to 0, which does not glow).
  std::vector<size_t> glowing;
  const TemperatureEmission e = make_temperature_emission(map, kDefaultEmissionIntensity, s["temperature"]["max"].get<double>());
  const double top_luminance = luminance_pyro_cli_vdb_fire(glm::dvec3(emitted_radiance(e, (hottest_kelvin - map.offset) / map.scale)));
  for (size_t i = 0; i < file.temperature.size(); ++i)
    if (luminance_pyro_cli_vdb_fire(glm::dvec3(emitted_radiance(e, file.temperature[i]))) >= 0.01 * top_luminance) glowing.push_back(i);
  ASSERT_GE(glowing.size(), 6u);
  std::sort(glowing.begin(), glowing.end(), [&](size_t a, size_t b) { return file.temperature[a] < file.temperature[b]; });
  const auto light_of = [&](size_t from, size_t to, const std::string& name) {
    ParticleFile part = file;
    for (float& t : part.temperature) t = 0.0f;
    for (size_t k = from; k < to; ++k) part.temperature[glowing[k]] = file.temperature[glowing[k]];
    const fs::path sub = dir / name;
    fs::create_directories(sub);
    write_particle_file((sub / "part.pyrop").string(), part);
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& l : emitted_light(sub, (sub / "part.pyrop").string())) sum += l;
    return sum;
  };
  const size_t third = glowing.size() / 3;
  const glm::dvec3 cool = light_of(0, third, "coolest"), warm = light_of(glowing.size() - third, glowing.size(), "hottest");
  std::printf("red/green: hottest third %.3f, coolest third %.3f (%zu glowing particles)\n", warm.x / warm.y,
              cool.x / cool.y, glowing.size());
  EXPECT_GT(cool.x / cool.y, warm.x / warm.y);
}

}  // namespace
}  // namespace pyro
