#pragma once
// Umenhoffer et al. 2006, section 4 and 5: what reduced-resolution media layers buy (Figure 12:
// 35, 60, 110, 185 fps at 1, 1/2, 1/4, 1/8) and Table 1 (frame rates for 0 to 1578 particles,
// planar and spherical, half-resolution layers).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pyro::cli {

struct LayersBenchOptions {
  std::string scene;
  int width = 512, height = 512;
  int frames = 60;        // timed frames per scale
  int error_frames = 4;   // frames (spread over the timed ones) where RMSE is measured
  bool sync_timing = false;  // per-system times include their GPU work (slower frames)
  std::vector<float> scales{1.0f, 0.5f, 0.25f, 0.125f};  // speed-ups are against the first
  // How the reduced layers are upsampled (systems/composite/compositor.h, MediaComposition):
  // true: depth-aware (the engine's default); false: plain bilinear.
  bool depth_aware = true;
  // The final pass in tiles sorted by the work they need (MediaComposition::tiles); false: the
  // full variant on every pixel.
  bool compose_tiles = true;
  // Billboards as point sprites where they fit (RenderSettings::billboard_sprites); false: quads.
  bool billboard_sprites = true;
};

// Per layer scale 1, 1/2, 1/4, 1/8: fps over the same frames, and against the full-resolution
// layers (at scale 1 nothing is upsampled) the RMSE (linear rgb, the composed view), and near the
// scene's depth edges edge_rmse and halo (engine/math/depth_edge_error.h; halo_rms beside it).
nlohmann::json bench_layers(const LayersBenchOptions& options);

struct Table1BenchOptions {
  std::string scene = "content/scenes/explosion.json";
  int width = 512, height = 512;
  int frames = 60;
};

// The scene's emitters scaled to 0, 263, 526, 1052, 1578 particles (counts and budgets times
// k = n / 263, radii times 1 / sqrt(k), so the covered screen area stays about constant: the
// paper's "billboard sizes are decreased proportionally"), planar and spherical, half-resolution
// layers; fps per row beside the paper's.
nlohmann::json bench_table1(const Table1BenchOptions& options);

}  // namespace pyro::cli
