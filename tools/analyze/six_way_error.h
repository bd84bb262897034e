#pragma once
// pyro analyze six-way: how well six-way lightmaps relight a smoke frame under lights between
// their axes. One simulation state of a lit scene (frame `frame`, drawn mono at the given size)
// is baked both ways, by the engine's GL passes (six_way_bake.h, rounded to the textures' 8 bits)
// and by the CPU reference (systems/runtime/reference/lit_particle_reference.h: single scattering
// with the sun's transmittance exact at every point, over black); each is relit by the six-way
// blend (six_way_frame.h) for the 8 diagonal lights (+-1, +-1, +-1)/sqrt(3) of the camera's frame
// and compared (RMSE, linear RGB clamped to [0, 1]) with the reference lit from that direction. The
// engine's own render lit from the direction is scored too: what the engine gets without the
// lightmaps; and the engine's relit bake against it, the blend's own error inside the engine.
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct SixWayErrorOptions {
  int frame = 24;
  int width = 64, height = 96;  // small: the CPU reference draws the state 15 times
};

struct SixWayDirectionError {
  glm::vec3 towards_light{0.0f};   // camera-facing frame, unit
  double six_way_engine = 0.0;     // the engine's bake (8-bit), relit
  double six_way_reference = 0.0;  // the reference's own six faces (float), relit
  double engine_lit = 0.0;         // the engine's render lit from the direction
  // The engine's bake relit against the engine's render lit from the direction: what the blend
  // alone costs inside the engine.
  double six_way_engine_vs_engine_lit = 0.0;
};

struct SixWayErrorReport {
  size_t particles = 0;
  std::vector<SixWayDirectionError> directions;  // the 8 diagonals
  // The reference (left) and the relit engine bake (right) for two lights, lit from the
  // upper right front and from the upper left behind the smoke, side by side.
  RgbImage picture;
  double seconds = 0.0;
};

// The 8 diagonal directions (+-1, +-1, +-1)/sqrt(3), x slowest, + before -.
std::vector<glm::vec3> six_way_diagonals();

// Checks the scene as a six-way bake does (check_six_way_bake) and measures.
SixWayErrorReport measure_six_way_error(const SceneDescription& scene,
                                        const SixWayErrorOptions& options);

}  // namespace pyro
