#pragma once
// Command-line options shared by the commands that render a scene: stereo mode, billboard
// alignment, layer scale, eye separation.
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "systems/scene_runtime/runtime_options.h"
#include "tools/pyro/print_note.h"

namespace pyro::cli {

inline const std::map<std::string, StereoMode>& stereo_mode_names() {
  static const std::map<std::string, StereoMode> names = {
      {"mono", StereoMode::mono},
      {"left-right", StereoMode::left_right},
      {"side-by-side", StereoMode::side_by_side},
      {"side-by-side-crossed", StereoMode::side_by_side_crossed},
      {"anaglyph", StereoMode::anaglyph},
      {"anaglyph-color", StereoMode::anaglyph_color},
      {"anaglyph-half-color", StereoMode::anaglyph_half_color}};
  return names;
}

inline const std::map<std::string, BillboardAlignment>& alignment_names() {
  static const std::map<std::string, BillboardAlignment> names = {
      {"viewplane", BillboardAlignment::viewplane}, {"viewpoint", BillboardAlignment::viewpoint}};
  return names;
}

inline const std::map<std::string, ParticleShape>& particle_shape_names() {
  static const std::map<std::string, ParticleShape> names = {{"gaussian", ParticleShape::gaussian},
                                                             {"spherical", ParticleShape::spherical},
                                                             {"planar", ParticleShape::planar}};
  return names;
}

// Adds --stereo, --billboards, --particles, --layer-scale, --interocular, --zero-parallax.
// The runtime's notes go to stderr.
inline void add_render_options(CLI::App* cmd, RuntimeOptions& o) {
  o.on_note = print_note;
  cmd->add_option("--stereo", o.stereo_mode,
                  "Stereo output: mono, left-right (two files per frame), side-by-side, "
                  "side-by-side-crossed, anaglyph (Dubois red-cyan), anaglyph-color, "
                  "anaglyph-half-color")
      ->transform(CLI::CheckedTransformer(stereo_mode_names(), CLI::ignore_case));
  cmd->add_option_function<std::string>(
         "--billboards",
         [&o](const std::string& v) { o.alignment = alignment_names().at(v); },
         "Billboard alignment: viewplane or viewpoint (default: the scene's)")
      ->check(CLI::IsMember(alignment_names()));
  cmd->add_option_function<std::string>(
         "--particles",
         [&o](const std::string& v) { o.particles = particle_shape_names().at(v); },
         "Particles as gaussian splats, spherical billboards or planar billboards (default: the scene's)")
      ->check(CLI::IsMember(particle_shape_names()));
  cmd->add_option_function<float>(
         "--layer-scale", [&o](float v) { o.layer_scale = v; },
         "Particle layer resolution as a fraction of the frame: 1, 0.5, 0.25, 0.125")
      ->check(CLI::IsMember({1.0f, 0.5f, 0.25f, 0.125f}));
  cmd->add_option("--frame-scale", o.frame_scale,
                  "Render the views at this fraction of the output size, then upscale: 1, 0.5, 0.25")
      ->check(CLI::IsMember({1.0f, 0.5f, 0.25f}));
  cmd->add_option_function<std::string>(
         "--eye-order", [&o](const std::string& v) { o.swap_eyes = v == "right-left"; },
         "left-right (default) or right-left: which eye goes where the left view is expected")
      ->check(CLI::IsMember({"left-right", "right-left"}));
  cmd->add_option_function<float>(
         "--interocular", [&o](float v) { o.interocular = v; },
         "Eye separation in world units (default: the scene's)")
      ->check(CLI::Range(0.0f, 1000.0f));
  cmd->add_option_function<float>(
         "--zero-parallax", [&o](float v) { o.zero_parallax_distance = v; },
         "View depth of the zero-parallax plane (default: the scene's)")
      ->check(CLI::Range(1e-4f, 1e6f));
}

}  // namespace pyro::cli
