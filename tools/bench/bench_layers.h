#pragma once
// Umenhoffer et al. 2006, section 4 and 5: what reduced-resolution media layers buy (Figure 12:
// 35, 60, 110, 185 fps at 1, 1/2, 1/4, 1/8) and Table 1 (frame rates for 0 to 1578 particles,
// planar and spherical, half-resolution layers).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/enum_names.h"
#include "engine/core/progress_sink.h"

namespace pyro {

// The methods the bench compares (`pyro bench layers --upsampling / --compose / --billboards`):
// the engine's default first, each against the plainer method it replaces.
// depth-aware: the compositor's depth-aware upsampling (the default); bilinear: plain bilinear.
enum class LayerUpsampling { depth_aware, bilinear };
inline constexpr EnumName<LayerUpsampling> layer_upsampling_names[] = {
    {LayerUpsampling::depth_aware, "depth-aware"}, {LayerUpsampling::bilinear, "bilinear"}};
constexpr const auto& enum_names(LayerUpsampling) { return layer_upsampling_names; }
// tiled: each screen tile runs only the work it needs; per-pixel: the full variant everywhere.
enum class ComposeMode { tiled, per_pixel };
inline constexpr EnumName<ComposeMode> compose_mode_names[] = {{ComposeMode::tiled, "tiled"},
                                                               {ComposeMode::per_pixel, "per-pixel"}};
constexpr const auto& enum_names(ComposeMode) { return compose_mode_names; }
// sprites: a point sprite per particle where it fits; quads: a quad per particle.
enum class BillboardGeometry { sprites, quads };
inline constexpr EnumName<BillboardGeometry> billboard_geometry_names[] = {
    {BillboardGeometry::sprites, "sprites"}, {BillboardGeometry::quads, "quads"}};
constexpr const auto& enum_names(BillboardGeometry) { return billboard_geometry_names; }

struct LayersBenchOptions {
  std::string scene;
  int width = 512, height = 512;
  int frames = 60;        // timed frames per scale
  int error_frames = 4;   // frames (spread over the timed ones) where RMSE is measured
  bool sync_timing = false;  // per-system times include their GPU work (slower frames)
  std::vector<float> scales{1.0f, 0.5f, 0.25f, 0.125f};  // speed-ups are against the first
  // How the reduced layers are upsampled (systems/composite/compositor.h, MediaComposition).
  LayerUpsampling upsampling = LayerUpsampling::depth_aware;
  // The final pass in tiles sorted by the work they need (MediaComposition::tiles), or the full
  // variant on every pixel.
  ComposeMode compose = ComposeMode::tiled;
  // Billboards as point sprites where they fit (RenderSettings::billboard_sprites), or quads.
  BillboardGeometry billboards = BillboardGeometry::sprites;
  ProgressSink* progress = nullptr;  // how far the run is (null: not reported)
};

// Per layer scale 1, 1/2, 1/4, 1/8: fps over the same frames, and against the full-resolution
// layers (at scale 1 nothing is upsampled) the RMSE (linear rgb, the composed view), and near the
// scene's depth edges edge_rmse and halo (engine/math/depth_edge_error.h; halo_rms beside it).
nlohmann::json bench_layers(const LayersBenchOptions& options);

struct Table1BenchOptions {
  std::string scene = "content/scenes/explosion.json";
  int width = 512, height = 512;
  int frames = 60;
  ProgressSink* progress = nullptr;  // how far the run is (null: not reported)
};

// The scene's emitters scaled to 0, 263, 526, 1052, 1578 particles (counts and budgets times
// k = n / 263, radii times 1 / sqrt(k), so the covered screen area stays about constant: the
// paper's "billboard sizes are decreased proportionally"), planar and spherical, half-resolution
// layers; fps per row beside the paper's.
nlohmann::json bench_table1(const Table1BenchOptions& options);

}  // namespace pyro
