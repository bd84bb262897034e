#include "tools/bench/bench_cycles_scene.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/png_file.h"
#include "engine/io/scratch_folder.h"
#include "engine/math/color.h"
#include "engine/math/highlight_rolloff.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "tools/bench/cycles_render.h"
#include "tools/bench/cycles_scene_request.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

// The frame's longer side unless --width and --height are given: Cycles' two renders of a cloud
// at 256 samples take minutes at this size on two cores.
constexpr int kDefaultLongerSide = 240;

// Linear radiance as a display shows it (engine/math/image_error.h): highlights rolled off.
RgbImage rolled_off(const RgbImage& linear) {
  RgbImage out = linear;
  for (size_t i = 0; i + 2 < out.rgb.size(); i += 3) {
    const glm::vec3 c = roll_off_highlights({linear.rgb[i], linear.rgb[i + 1], linear.rgb[i + 2]});
    for (int k = 0; k < 3; ++k) out.rgb[i + k] = c[k];
  }
  return out;
}

// A rolled-off image sRGB-encoded, as the frame's PNG holds it (engine/io/png_file.cpp).
RgbImage encoded(const RgbImage& rolled) {
  RgbImage out = rolled;
  for (float& v : out.rgb) v = linear_to_srgb(std::clamp(v, 0.0f, 1.0f));
  return out;
}

double clamped(float v) { return std::clamp(double(v), 0.0, 1.0); }

struct RegionSums {
  std::array<double, kFrameRegions> squared{}, noise{}, difference{};
  std::array<int, kFrameRegions> pixels{};
};

// Per region: the squared differences of `a` and `b` (and of Cycles' two renders, `b2`), summed.
RegionSums region_sums(const RgbImage& a, const RgbImage& b, const RgbImage* b2, const std::vector<FrameRegion>& r) {
  RegionSums s;
  for (size_t p = 0; p < r.size(); ++p) {
    const int k = int(r[p]);
    ++s.pixels[k];
    for (int c = 0; c < 3; ++c) {
      const double d = clamped(a.rgb[3 * p + c]) - clamped(b.rgb[3 * p + c]);
      s.squared[k] += d * d;
      s.difference[k] += d;
      if (b2) {
        const double n = clamped(b.rgb[3 * p + c]) - clamped(b2->rgb[3 * p + c]);
        s.noise[k] += n * n;
      }
    }
  }
  return s;
}

nlohmann::json score(const RgbImage& ours, const RgbImage& cycles, const RgbImage* cycles2,
                     const std::vector<FrameRegion>& regions, nlohmann::json& j) {
  const RgbImage a = rolled_off(ours), b = rolled_off(cycles);
  std::optional<RgbImage> b2;
  if (cycles2) b2 = rolled_off(*cycles2);
  const RegionSums s = region_sums(a, b, b2 ? &*b2 : nullptr, regions);
  double total = 0.0, noise = 0.0;
  for (int k = 0; k < kFrameRegions; ++k) total += s.squared[k], noise += s.noise[k];
  const double n = 3.0 * double(regions.size());
  j["rmse"] = std::sqrt(total / n);
  j["srgb_rmse"] = image_rmse(encoded(a), encoded(b));
  j["cycles_noise"] = b2 ? nlohmann::json(std::sqrt(noise / n / 2.0)) : nlohmann::json(nullptr);
  nlohmann::json out = nlohmann::json::object();
  int largest = 0;
  for (int k = 0; k < kFrameRegions; ++k) {
    if (s.squared[k] > s.squared[largest]) largest = k;
    const double m = 3.0 * std::max(1, s.pixels[k]);
    out[frame_region_name(FrameRegion(k))] = {
        {"pixels", s.pixels[k]},
        {"share", double(s.pixels[k]) / double(regions.size())},
        {"rmse", s.pixels[k] ? nlohmann::json(std::sqrt(s.squared[k] / m)) : nlohmann::json(nullptr)},
        {"cycles_noise", b2 && s.pixels[k] ? nlohmann::json(std::sqrt(s.noise[k] / m / 2.0)) : nlohmann::json(nullptr)},
        {"mean_difference", s.pixels[k] ? nlohmann::json(s.difference[k] / m) : nlohmann::json(nullptr)},
        {"squared_error_share", total > 0.0 ? s.squared[k] / total : 0.0}};
  }
  j["largest_region"] = frame_region_name(FrameRegion(largest));
  return out;
}

// The engine's frame, Cycles' and the regions (sky black, media blue, lit surfaces yellow, shadowed
// surfaces purple) side by side, as shown.
void write_side_by_side(const std::string& path, const RgbImage& ours, const RgbImage& cycles,
                        const std::vector<FrameRegion>& regions) {
  const int w = ours.width, h = ours.height;
  const RgbImage a = encoded(rolled_off(ours)), b = encoded(rolled_off(cycles));
  static const std::array<std::array<uint8_t, 3>, kFrameRegions> colours{
      {{0, 0, 0}, {60, 110, 230}, {235, 200, 60}, {120, 60, 140}}};
  std::vector<uint8_t> pixels(size_t(3) * 3 * w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t row = size_t(y) * 3 * w;
        const size_t p = size_t(y) * w + x;
        pixels[3 * (row + x) + c] = uint8_t(std::lround(255.0 * clamped(a.rgb[3 * p + c])));
        pixels[3 * (row + w + x) + c] = b.rgb.empty() ? 0 : uint8_t(std::lround(255.0 * clamped(b.rgb[3 * p + c])));
        pixels[3 * (row + 2 * w + x) + c] = colours[size_t(regions[p])][size_t(c)];
      }
  write_png(path, 3 * w, h, 3, pixels);
}

CyclesRender render_scene_with_cycles(const CyclesSceneBenchOptions& o, nlohmann::json request, int seed,
                                      const fs::path& scratch) {
  const fs::path out = scratch / ("cycles_" + std::to_string(seed) + ".pfm");
  const fs::path file = scratch / ("request_" + std::to_string(seed) + ".json");
  request["samples"] = o.samples;
  request["bounces"] = o.bounces;
  request["seed"] = seed;
  request["out"] = out.string();
  std::ofstream(file) << request.dump();
  const std::string cmd = blender_script_command(o.blender, "cycles/render_scene.py") + " " + shell_quoted(file.string());
  return run_cycles(cmd, out, request["width"].get<int>(), request["height"].get<int>(), scratch / "cycles.log",
                    o.on_note);
}

}  // namespace

nlohmann::json bench_cycles_scene(const CyclesSceneBenchOptions& o) {
  const SceneDescription scene = load_scene(o.scene);
  OutputGate().reads(scene_inputs(o.scene, scene)).writes_file(o.image, "--image").check();
  if (!program_exists(o.blender))
    throw UserError(o.blender, "--blender",
                    "the blender program, on PATH or as a path (Debian: apt-get install --no-install-recommends blender)");
  ProgressTask progress(o.progress, "bench cycles-scene", 4);
  const ScratchFolder scratch("pyro-bench-cycles-scene");
  OpenSceneOptions open;
  open.description = scene;
  open.on_note = o.on_note;
  open.runtime.on_note = o.on_note;
  open.runtime.readback = true;
  const double fit = double(kDefaultLongerSide) / std::max(scene.width, scene.height);
  open.runtime.width_override = o.width > 0 ? o.width : std::max(1, int(std::lround(scene.width * fit)));
  open.runtime.height_override = o.height > 0 ? o.height : std::max(1, int(std::lround(scene.height * fit)));
  progress.stage(0, "engine frame");
  const auto t0 = std::chrono::steady_clock::now();
  const OpenedScene opened = open_scene(o.scene, open);
  opened.runtime->draw_frame(o.frame);
  const RgbImage ours = rgb_of(opened.runtime->image());
  const double engine_seconds = seconds_since(t0);
  progress.stage(1, "media grid and regions");
  CyclesSceneOptions options;
  options.voxel_error = o.voxel_error;
  options.vdb = (scratch.path / "media.vdb").string();
  const CyclesScene cs = cycles_scene_of(opened.runtime->world(), options);
  nlohmann::json request = cs.request;
  const glm::vec3 bg = opened.runtime->scene().background;
  request["background"] = {bg.x, bg.y, bg.z};
  RegionScene regions_scene;
  regions_scene.triangles = cs.triangles;
  regions_scene.media = cs.media.box.voxels() ? &cs.media : nullptr;
  regions_scene.toward_key = cs.toward_key;
  regions_scene.threads = o.threads;
  const std::vector<FrameRegion> regions = frame_regions(regions_scene, cs.camera);
  nlohmann::json j = {{"scene", o.scene}, {"frame", o.frame}, {"width", ours.width}, {"height", ours.height},
                      {"samples", o.samples}, {"bounces", o.bounces}, {"particles", cs.particles},
                      {"voxel_size", cs.media.box.voxels() ? nlohmann::json(cs.media.box.voxel) : nlohmann::json(nullptr)},
                      {"voxel_error", cs.voxel_error}, {"approximations", cs.approximations},
                      {"engine_seconds", engine_seconds}, {"cycles_seconds", nullptr}, {"rmse", nullptr},
                      {"srgb_rmse", nullptr}, {"cycles_noise", nullptr}, {"largest_region", nullptr},
                      {"regions", nullptr}};
  progress.stage(2, "Cycles, first seed");
  const CyclesRender a = render_scene_with_cycles(o, request, 1, scratch.path);
  if (a.image.rgb.empty()) return j;
  j["cycles_seconds"] = a.seconds;
  progress.stage(3, "Cycles, second seed");
  const CyclesRender b = render_scene_with_cycles(o, request, 2, scratch.path);
  j["regions"] = score(ours, a.image, b.image.rgb.empty() ? nullptr : &b.image, regions, j);
  if (!o.image.empty()) write_side_by_side(o.image, ours, a.image, regions);
  progress.finish();
  return j;
}

}  // namespace pyro
