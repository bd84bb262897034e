#pragma once
// Resource: what the render systems need from the scene that is not an entity.
#include "engine/core/enum_names.h"
#include <glm/vec3.hpp>

#include "components/render_modes.h"

namespace pyro {

// How the views of a frame become images (pyro render --stereo).
enum class StereoMode {
  mono,                  // one view, one image
  left_right,            // two views, two images per frame (_left, _right)
  side_by_side,          // two views in one image, left eye on the left (parallel viewing)
  side_by_side_crossed,  // right eye on the left (cross-eyed viewing)
  anaglyph,              // red-cyan, Dubois least-squares matrices
  anaglyph_color,        // red-cyan, colour anaglyph
  anaglyph_half_color,   // red-cyan, half-colour anaglyph
};
// The names of the scene file, the command line (--stereo), the viewer and the reports.
inline constexpr EnumName<StereoMode> stereo_mode_names[] = {
    {StereoMode::mono, "mono"},
    {StereoMode::left_right, "left-right"},
    {StereoMode::side_by_side, "side-by-side"},
    {StereoMode::side_by_side_crossed, "side-by-side-crossed"},
    {StereoMode::anaglyph, "anaglyph"},
    {StereoMode::anaglyph_color, "anaglyph-color"},
    {StereoMode::anaglyph_half_color, "anaglyph-half-color"}};
constexpr const auto& enum_names(StereoMode) { return stereo_mode_names; }

inline bool is_stereo(StereoMode m) { return m != StereoMode::mono; }
// Both views side by side in one output (or split into two files from it): twice as wide.
inline bool two_views_wide(StereoMode m) {
  return m == StereoMode::side_by_side || m == StereoMode::side_by_side_crossed ||
         m == StereoMode::left_right;
}

// The output's width for views of `view_width` pixels: two views side by side or one.
inline int output_width(int view_width, StereoMode m) {
  return two_views_wide(m) ? 2 * view_width : view_width;
}

// What the frames hold where neither medium nor mesh covers the background (scene key
// output.background, pyro render --background): the background colour, opaque; or nothing, the
// frames' alpha then the coverage of the media and the meshes (systems/output/
// transparent_frame.h).
enum class OutputBackground { opaque, none };
inline constexpr EnumName<OutputBackground> output_background_names[] = {
    {OutputBackground::opaque, "opaque"}, {OutputBackground::none, "none"}};
constexpr const auto& enum_names(OutputBackground) { return output_background_names; }

struct RenderSettings {
  int width = 800;
  int height = 600;
  glm::vec3 background{0.62f, 0.68f, 0.76f};  // linear RGB
  // OutputBackground::none: the scene targets are cleared to the background with alpha 0, so that
  // alpha carries the coverage through the composite (the colours stay those of the opaque frame).
  bool transparent = false;
  // The lights are entities (components/directional_light.h, ambient_light.h), gathered each
  // frame by the light phase into SceneLighting (components/scene_lighting.h).
  BillboardAlignment alignment = BillboardAlignment::viewplane;
  ParticleShape particles = ParticleShape::gaussian;
  float layer_scale = 1.0f;  // particle layer size as a fraction of the rendered views
  // The views (opaque scene, particles, composition) render at this fraction of the output
  // size and the composed image is upscaled to it: a shortcut whose error the benchmarks report.
  float frame_scale = 1.0f;
  StereoMode stereo_mode = StereoMode::mono;
  // Motion blur: output = (1 - b) new + b previous output, linear (scene key render.motion_blur).
  float motion_blur = 0.0f;
  // Spherical and planar billboards as point sprites where they fit, else quads
  // (systems/billboard_render/sphere_billboard_programs.h); off: quads throughout, to compare.
  bool billboard_sprites = true;
  // Leave out of the draw lists the particles no view can show, before sorting them
  // (systems/sorting/depth_sort.h); off: every particle is sorted and drawn, to compare.
  bool cull_particles = true;
  // Where the Gaussian splats' draw order is made (components/render_modes.h).
  SortDevice sort_device = SortDevice::automatic;
  // explosion: dust, smoke and fire each in its own layer at layer_scale (components/gpu_frame.h).
  ParticleShading shading = ParticleShading::color;
  bool media_layers() const {
    return shading == ParticleShading::explosion && particles != ParticleShape::gaussian;
  }
};

}  // namespace pyro
