#include "systems/runtime/open_scene/flipbook_bake.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "components/particle_set.h"
#include "components/view.h"
#include "engine/core/content_path.h"
#include "engine/core/user_error.h"
#include "systems/runtime/scene/scene_loader.h"
#include "engine/io/exr_file.h"
#include "engine/io/png_file.h"
#include "engine/io/folder_replacement.h"
#include "engine/math/color.h"
#include "engine/io/text_file.h"
#include "systems/flipbook_fire/flipbook_atlas_sidecar.h"
#include "systems/flipbook_fire/flipbook_motion.h"
#include "systems/flipbook_fire/particle_motion_splat.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene_runtime/default_flipbook.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

void check_flipbook_bake(const SceneDescription& scene, const FlipbookBakeOptions& options,
                         const std::string& out) {
  namespace fs = std::filesystem;
  if (!scene.fires.empty())
    throw UserError(scene.file, "/fires",
                    "expected a scene of simulated fire to bake, found flipbook fires (a bake "
                    "renders emitters, not flipbooks)");
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw UserError(out, "--out", "expected a folder for the flipbook frames, found a file");
  if (options.loop_blend < 0 || options.loop_blend >= options.frames)
    throw UserError("", "--loop-blend",
                    "expected a cross-fade shorter than the flipbook (0 to " +
                        std::to_string(options.frames - 1) + " frames), found " +
                        std::to_string(options.loop_blend));
  const long long tiles = static_cast<long long>(options.atlas_columns) * options.atlas_rows;
  if ((options.atlas_columns > 0 || options.atlas_rows > 0) && tiles < options.frames)
    throw UserError("", "--atlas",
                    "expected a grid with room for the " + std::to_string(options.frames) +
                        " frames, found " + std::to_string(options.atlas_columns) + "x" +
                        std::to_string(options.atlas_rows) + " = " + std::to_string(tiles) + " tiles");
}

RuntimeOptions flipbook_runtime_options(const FlipbookBakeOptions& options) {
  RuntimeOptions runtime_options;
  runtime_options.readback = false;
  runtime_options.width_override = options.width;
  runtime_options.height_override = options.height;
  return runtime_options;
}

FlipbookBakeResult bake_flipbook(const SceneDescription& scene, const FlipbookBakeOptions& options,
                                 const std::string& out) {
  check_flipbook_bake(scene, options, out);
  const auto t0 = std::chrono::steady_clock::now();
  const std::unique_ptr<SceneRuntime> runtime = open_runtime(scene, flipbook_runtime_options(options));
  FlipbookBakeResult result = bake_flipbook(*runtime, options, out);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

namespace {

bool bakes_atlas(const FlipbookBakeOptions& options) { return options.atlas_columns > 0; }

// What the simulation gave, frames + loop_blend of them: RGBA8 sRGB images and, for an atlas,
// the medium's motion.
struct SimulatedFrames {
  int width = 0, height = 0;
  std::vector<std::vector<uint8_t>> rgba;
  std::vector<MotionSums> motion;
  std::vector<std::vector<float>> linear;  // for an atlas: linear RGBA, premultiplied
};

// The frame just drawn, linear, for the EXR atlas: the one view, at the shown frame's size.
std::vector<float> linear_frame(SceneRuntime& runtime, int width, int height) {
  std::vector<LinearView> views = runtime.read_linear(false);
  if (views.size() != 1 || views[0].width != width || views[0].height != height)
    throw UserError(runtime.scene().file, "/quality",
                    "expected a mono scene drawn at full size for the linear (EXR) atlas, found " +
                        std::to_string(views.size()) + " view(s) of " +
                        (views.empty() ? std::string("no size")
                                       : std::to_string(views[0].width) + "x" + std::to_string(views[0].height)) +
                        " for a " + std::to_string(width) + "x" + std::to_string(height) + " frame");
  return std::move(views[0].rgba);
}

// The particles of every set in the world, as the motion splat takes them.
std::vector<MotionParticle> motion_particles(ecs::World& world) {
  std::vector<MotionParticle> out;
  world.each<const ParticleSet>([&](const ParticleSet& set) {
    const ParticlePool& p = set.pool;
    for (size_t i = 0; i < p.size(); ++i)
      out.push_back({{p.px[i], p.py[i], p.pz[i]}, {p.vx[i], p.vy[i], p.vz[i]}, p.radius[i],
                     p.opacity[i] * p.density[i]});
  });
  return out;
}

SimulatedFrames simulate(SceneRuntime& runtime, const FlipbookBakeOptions& options) {
  SimulatedFrames sim;
  const float dt = 1.0f / runtime.scene().frames_per_second;
  for (int f = 0; f < options.frames + options.loop_blend; ++f) {
    runtime.step();
    ShownImage image = runtime.read_output();
    sim.width = image.width;
    sim.height = image.height;
    sim.rgba.push_back(std::move(image.rgba));
    if (!bakes_atlas(options)) continue;
    sim.linear.push_back(linear_frame(runtime, sim.width, sim.height));
    MotionSums& sums = sim.motion.emplace_back(image.width, image.height);
    if (const View* view = runtime.world().try_resource<const View>())
      splat_particle_motion(motion_particles(runtime.world()), view->frame, dt, sums);
  }
  return sim;
}

// Weight of simulated frame f in written frame f (the loop's cross-fade; 1 past it).
float own_weight(int f, const FlipbookBakeOptions& options) {
  if (f >= options.loop_blend) return 1.0f;
  return static_cast<float>(f + 1) / static_cast<float>(options.loop_blend + 1);
}

// Written frame f, RGB8 sRGB: cross-faded in linear light with simulated frame frames + f
// (weight own_weight on frame f), then faded at the borders.
std::vector<uint8_t> written_frame(const SimulatedFrames& sim, int f, const FlipbookBakeOptions& options) {
  const size_t pixels = static_cast<size_t>(sim.width) * sim.height;
  std::vector<uint8_t> rgb(pixels * 3);
  const std::vector<uint8_t>& a = sim.rgba[static_cast<size_t>(f)];
  if (f < options.loop_blend) {
    const std::vector<uint8_t>& b = sim.rgba[static_cast<size_t>(options.frames + f)];
    const float w = own_weight(f, options);
    for (size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) {
        const float la = srgb_to_linear(a[i * 4 + c] / 255.0f), lb = srgb_to_linear(b[i * 4 + c] / 255.0f);
        rgb[i * 3 + c] = to_byte(linear_to_srgb(w * la + (1.0f - w) * lb));
      }
  } else {
    for (size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = a[i * 4 + c];
  }
  apply_frame_fade(options.fade, sim.width, sim.height, rgb);
  return rgb;
}

// Written frame f, linear RGBA (premultiplied) for the EXR atlas: the same cross-fade and border
// fade as the PNG frame's, on every channel, without the shown frame's roll-off or rounding.
std::vector<float> written_linear(const SimulatedFrames& sim, int f, const FlipbookBakeOptions& options) {
  std::vector<float> out = sim.linear[static_cast<size_t>(f)];
  if (f < options.loop_blend) {
    const std::vector<float>& b = sim.linear[static_cast<size_t>(options.frames + f)];
    const float w = own_weight(f, options);
    for (size_t i = 0; i < out.size(); ++i) out[i] = w * out[i] + (1.0f - w) * b[i];
  }
  for (int y = 0; y < sim.height; ++y)
    for (int x = 0; x < sim.width; ++x) {
      const float k = frame_fade_weight(options.fade, sim.width, sim.height, x, y);
      for (int c = 0; c < 4; ++c) out[(static_cast<size_t>(y) * sim.width + x) * 4 + c] *= k;
    }
  return out;
}

// A motion field as RGBA floats for the EXR motion atlas: R = u, G = v up (the PNG's axes,
// unscaled and unbiased), B = 0, A = 1.
std::vector<float> motion_floats(const MotionField& m) {
  std::vector<float> out(static_cast<size_t>(m.width) * m.height * 4);
  for (size_t i = 0; i < out.size() / 4; ++i) {
    out[i * 4 + 0] = m.uv[i * 2];
    out[i * 4 + 1] = -m.uv[i * 2 + 1];
    out[i * 4 + 2] = 0.0f;
    out[i * 4 + 3] = 1.0f;
  }
  return out;
}

// Written frame f's motion: the same cross-fade of the simulated frames' motion sums.
MotionField written_motion(const SimulatedFrames& sim, int f, const FlipbookBakeOptions& options) {
  MotionSums sums(sim.width, sim.height);
  const float w = own_weight(f, options);
  sums.add(sim.motion[static_cast<size_t>(f)], w);
  if (f < options.loop_blend) sums.add(sim.motion[static_cast<size_t>(options.frames + f)], 1.0f - w);
  MotionField field = sums.field();
  // The border fade is a window fixed to the frame, not carried by the medium: where it dims the
  // flame, the motion is dimmed with it, so that a blend does not slide the window's edge.
  for (int y = 0; y < sim.height; ++y)
    for (int x = 0; x < sim.width; ++x) {
      const float k = frame_fade_weight(options.fade, sim.width, sim.height, x, y);
      const size_t i = (static_cast<size_t>(y) * sim.width + x) * 2;
      field.uv[i] *= k;
      field.uv[i + 1] *= k;
    }
  return field;
}

void write_frame_folder(const SimulatedFrames& sim, const SceneDescription& scene,
                        const FlipbookBakeOptions& options, const std::string& out,
                        const FolderReplacement& staging, FlipbookBakeResult& result) {
  namespace fs = std::filesystem;
  for (int f = 0; f < options.frames; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", f);
    write_png((staging.path() / name).string(), sim.width, sim.height, 3, written_frame(sim, f, options));
    result.files.push_back((fs::path(out) / name).string());
  }
  const nlohmann::json manifest = {{"frames", options.frames},
                                   {"width", options.width},
                                   {"height", options.height},
                                   {"frames_per_second", scene.frames_per_second},
                                   {"loop_blend", options.loop_blend},
                                   {"source", scene.file}};
  write_text_file((staging.path() / "flipbook.json").string(), manifest.dump(2) + "\n");
  result.files.push_back((fs::path(out) / "flipbook.json").string());
}

// The EXR atlases beside the PNG ones: linear colour (half RGBA, premultiplied) and exact motion.
void write_linear_atlases(const SimulatedFrames& sim, const AtlasSidecar& s,
                          const std::vector<MotionField>& motion, const FlipbookBakeOptions& options,
                          const FolderReplacement& staging) {
  std::vector<std::vector<float>> colour, motion_tiles;
  for (int f = 0; f < options.frames; ++f) colour.push_back(written_linear(sim, f, options));
  for (const MotionField& m : motion) motion_tiles.push_back(motion_floats(m));
  ExrImage image;
  image.width = s.layout.width();
  image.height = s.layout.height();
  image.rgba = pack_atlas(s.layout, colour, 4);
  write_exr((staging.path() / s.linear_image).string(), image);
  image.rgba = pack_atlas(s.layout, motion_tiles, 4);
  write_exr((staging.path() / s.motion_linear_image).string(), image);
}

void write_atlas(const SimulatedFrames& sim, const SceneDescription& scene,
                 const FlipbookBakeOptions& options, const std::string& out,
                 const FolderReplacement& staging, FlipbookBakeResult& result) {
  namespace fs = std::filesystem;
  AtlasSidecar s;
  s.layout = {options.atlas_columns, options.atlas_rows, sim.width, sim.height};
  s.frames = options.frames;
  s.frames_per_second = scene.frames_per_second;
  s.scene = scene.file;
  s.loop_blend = options.loop_blend;
  s.engine_version = options.engine_version;
  s.motion_image = "motion.png";
  s.linear_image = "atlas.exr";
  s.motion_linear_image = "motion.exr";
  std::vector<std::vector<uint8_t>> colour, motion_tiles;
  std::vector<MotionField> motion;
  for (int f = 0; f < options.frames; ++f) {
    colour.push_back(written_frame(sim, f, options));
    motion.push_back(written_motion(sim, f, options));
  }
  s.motion_strength = motion_strength(motion);
  for (const MotionField& m : motion) motion_tiles.push_back(encode_motion(m, s.motion_strength));
  write_png((staging.path() / s.image).string(), s.layout.width(), s.layout.height(), 3,
            pack_atlas(s.layout, colour, 3));
  write_png((staging.path() / s.motion_image).string(), s.layout.width(), s.layout.height(), 4,
            pack_atlas(s.layout, motion_tiles, 4));
  write_linear_atlases(sim, s, motion, options, staging);
  write_text_file((staging.path() / "atlas.json").string(), atlas_sidecar_json(s).dump(2) + "\n");
  for (const std::string& name : {s.image, s.motion_image, s.linear_image, s.motion_linear_image,
                                  std::string("atlas.json")})
    result.files.push_back((fs::path(out) / name).string());
}

}  // namespace

FlipbookBakeResult bake_flipbook(SceneRuntime& runtime, const FlipbookBakeOptions& options,
                                 const std::string& out) {
  const auto t0 = std::chrono::steady_clock::now();
  FolderReplacement staging(out, flipbook_bake_output_kind(), options.overwrite);
  const SimulatedFrames sim = simulate(runtime, options);
  FlipbookBakeResult result;
  result.removed_leftovers = staging.removed_leftovers();
  result.restored_old_folder = staging.restored_old_folder();
  if (bakes_atlas(options))
    write_atlas(sim, runtime.scene(), options, out, staging, result);
  else
    write_frame_folder(sim, runtime.scene(), options, out, staging, result);
  staging.commit();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

std::string ensure_default_flipbook(const NoteSink& on_note) {
  const std::string folder = default_flipbook_folder();
  if (default_flipbook_baked()) return folder;
  const std::string scene = content_path("scenes/flipbook_fire.json");
  if (on_note)
    on_note("baking the default flame flipbook from " + scene + " into " + folder + " (first run)");
  bake_flipbook(load_scene(scene), FlipbookBakeOptions{}, folder);
  return folder;
}

}  // namespace pyro
