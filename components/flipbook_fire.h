#pragma once
// A flipbook fire (Rose 2007, chapter 4): billboards textured with an animated sequence of flame
// frames, arranged in groups (overlapped pairs, triplets, grids of rows x columns), the whole set
// rotated about the fire's vertical axis to face the viewer. Plain data: the scene file's keys
// (docs/scene_format.md, `fires[]`) map onto these fields one to one, and the runtime expands the
// groups into `billboards` (systems/flipbook_fire/flipbook_layout.h).
#include "engine/core/enum_names.h"
#include "engine/math/flame_flicker.h"
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace pyro {

// How a billboard's colour meets what is behind it (Rose 2007, section 4.3).
enum class FlipbookBlend {
  // glBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ONE): result = src (1 - dst) + dst, every channel.
  one_minus_destination,
  // glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA): result = src a + dst (1 - a).
  linear_alpha,
};
inline constexpr EnumName<FlipbookBlend> flipbook_blend_names[] = {
    {FlipbookBlend::one_minus_destination, "one-minus-destination"},
    {FlipbookBlend::linear_alpha, "linear-alpha"}};
constexpr const auto& enum_names(FlipbookBlend) { return flipbook_blend_names; }

// The thesis' preparation of video frames (section 4.2), applied when the frames are read:
// crop (x0, y0, x1, y1 as fractions of the frame, y down from the top), then a black line along
// the bottom (`base_line`, a fraction of the cropped height) and a soft ramp above it (`soften`,
// a fraction of the height over which the frame fades in from black: the smudge tool).
struct FlipbookPreparation {
  glm::vec4 crop{0.0f, 0.0f, 1.0f, 1.0f};
  float base_line = 0.0f;
  float soften = 0.0f;
};

// rows x columns billboards (section 4.4, figures 12, 16 and 19). In the fire's frame (lateral to
// the viewer's right, depth toward the viewer), billboard (r, c) sits at
//   lateral = offset.x + (c - (columns - 1) / 2) width (1 - overlap)
//   depth   = offset.y + (r - (rows - 1) / 2) row_spacing + column_depths[c mod size]
// (row 0 furthest from the viewer) and starts at frame
//   start_frames[c mod size] + r row_start_step, stepping by increments[c mod size].
// The thesis' pairs: 2 columns overlapped by 1/3, 0.1 apart in depth, rows 0.19 apart, starts
// (2, 10), +1 per row, increments m_k = 1, n_k = -2.
struct FlipbookGroup {
  glm::vec2 offset{0.0f, 0.0f};
  int rows = 3;
  int columns = 2;
  float overlap = 1.0f / 3.0f;                 // fraction of a billboard's width shared by neighbours
  float row_spacing = 0.19f;                   // world units between rows (depth)
  std::vector<float> column_depths{0.0f, 0.1f};  // per column, cycled
  std::vector<int> start_frames{2, 10};         // per column, cycled (frame numbers from 0)
  int row_start_step = 1;
  std::vector<int> increments{1, -2};           // per column, cycled; m_k, n_k (, l_k)
};

// One billboard after expansion: where it stands in the fire's frame and its frame sequence.
struct FlipbookBillboard {
  float lateral = 0.0f;
  float depth = 0.0f;
  int start_frame = 0;
  int increment = 1;
  int group = 0, row = 0, column = 0;
  int overlap_count = 1;    // billboards whose lateral extent covers this one's centre (itself too)
  float intensity = 1.0f;   // colour scale: fire intensity / overlap_count ^ overlap_exponent
};

struct FlipbookFire {
  std::string name;
  glm::vec3 position{0.0f};          // centre of the fire's base
  glm::vec3 up{0.0f, 1.0f, 0.0f};    // the base's normal: billboards stay perpendicular to the base
  float width = 0.3f;                // billboard width, world units
  float aspect = 1.5f;               // height / width (the thesis' 1:1.5)
  float intensity = 1.0f;            // colour scale of every billboard
  float overlap_exponent = 0.5f;     // colour scaled by overlap_count^-exponent
  FlipbookBlend blend = FlipbookBlend::one_minus_destination;
  float frames_per_second = 30.0f;   // flipbook time steps per second of scene time
  // The flame's puffing (engine/math/flame_flicker.h): its billboards' colour and its light scaled
  // by 1 + flicker n(t), n of unit rms around the puffing frequency; 0: steady (six-way smoke
  // always is).
  float flicker = 0.15f;
  float flicker_frequency = 0.0f;    // Hz; 0: the puffing frequency 1.5 / sqrt(width in metres)
  std::string flipbook;              // folder of PNG frames, resolved; empty: the engine's baked one
  FlipbookPreparation preparation;
  std::vector<FlipbookGroup> groups;
  // Filled when the world is built (systems/flipbook_fire/flipbook_world.h):
  std::vector<FlipbookBillboard> billboards;  // from `groups`
  int frame_count = 0;                        // frames in the flipbook
  int texture = -1;                           // index of its frames in the FlipbookRenderer
  bool motion_vectors = false;                // the flipbook has them: frames blend between steps
  bool six_way = false;                       // six-way lightmaps: smoke relit by the scene's light
};

// The fire's flicker: its amplitude, its frequency, and a seed from its name and place so that
// fires side by side puff out of step. Six-way smoke is lit, not alight: it holds steady.
inline FlameFlicker flicker_of(const FlipbookFire& fire) {
  uint32_t seed = 2166136261u;  // FNV-1a over the name's bytes and the position's
  const auto mix = [&seed](const void* bytes, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) seed = (seed ^ static_cast<const unsigned char*>(bytes)[i]) * 16777619u;
  };
  mix(fire.name.data(), fire.name.size());
  mix(&fire.position, sizeof(fire.position));
  const double frequency =
      fire.flicker_frequency > 0.0f ? double(fire.flicker_frequency) : puffing_frequency(double(fire.width));
  return {fire.six_way ? 0.0 : double(fire.flicker), frequency, seed};
}

}  // namespace pyro
