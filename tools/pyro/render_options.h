#pragma once
// Command-line options shared by the commands that render a scene: stereo mode, billboard
// alignment, particles, layer and frame scale, eye order and separation. The accepted names are
// the enums' own tables (engine/core/enum_names.h), so the scene file and the command line
// cannot drift apart.
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "components/render_modes.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "engine/core/enum_names.h"
#include "systems/runtime/scene_runtime/runtime_options.h"
#include "tools/pyro/print_note.h"

namespace pyro::cli {

// `--name` taking one of E's names: CLI11 refuses anything else, listing the names.
template <class E>
CLI::Option* add_enum_option(CLI::App* cmd, const std::string& name, std::function<void(E)> set,
                             const std::string& help) {
  return cmd
      ->add_option_function<std::string>(
          name, [set](const std::string& v) { set(*enum_from_name<E>(v)); },
          help + ": " + enum_name_list<E>())
      ->check(CLI::IsMember(enum_name_map<E>()));
}

// Adds --stereo, --billboards, --particles, --sort-device, --shadows, --layer-scale, --frame-scale, --eye-order,
// --interocular, --zero-parallax, --threads. The runtime's notes go to stderr.
inline void add_render_options(CLI::App* cmd, RuntimeOptions& o) {
  o.on_note = print_note;
  add_enum_option<StereoMode>(
      cmd, "--stereo", [&o](StereoMode m) { o.stereo_mode = m; },
      "Stereo output (left-right writes two files per frame; anaglyph is Dubois red-cyan)");
  add_enum_option<BillboardAlignment>(
      cmd, "--billboards", [&o](BillboardAlignment a) { o.alignment = a; },
      "Billboard alignment (default: the scene's)");
  add_enum_option<ParticleShape>(
      cmd, "--particles", [&o](ParticleShape p) { o.particles = p; },
      "Particles as Gaussian splats, spherical or planar billboards (default: the scene's)");
  add_enum_option<SortDevice>(
      cmd, "--sort-device", [&o](SortDevice d) { o.sort_device = d; },
      "Where the Gaussian splats' draw order is made (default: the scene's, auto)");
  cmd->add_option_function<std::string>(
         "--shadows",
         [&o](const std::string& v) {
           o.shadows_off = v == "off";
           if (!o.shadows_off) o.shadow_method = *enum_from_name<ShadowMethod>(v);
         },
         "Lit media and how their shadows are found: off (unlit, as without a \"shadows\" block), " +
             enum_name_list<ShadowMethod>() + " (default: the scene's)")
      ->check(CLI::IsMember([] {
        std::vector<std::string> names = {"off"};
        for (std::string_view n : enum_name_views<ShadowMethod>()) names.emplace_back(n);
        return names;
      }()));
  cmd->add_option_function<float>(
         "--layer-scale", [&o](float v) { o.layer_scale = v; },
         "Particle layer resolution as a fraction of the frame: 1, 0.5, 0.25, 0.125")
      ->check(CLI::IsMember({1.0f, 0.5f, 0.25f, 0.125f}));
  cmd->add_option("--frame-scale", o.frame_scale,
                  "Render the views at this fraction of the output size, then upscale: 1, 0.5, 0.25")
      ->check(CLI::IsMember({1.0f, 0.5f, 0.25f}));
  add_enum_option<EyeOrder>(
      cmd, "--eye-order", [&o](EyeOrder e) { o.swap_eyes = e == EyeOrder::right_left; },
      "Which eye goes where the left view is expected (default: the scene's)");
  cmd->add_option_function<float>(
         "--interocular", [&o](float v) { o.interocular = v; },
         "Eye separation in world units (default: the scene's)")
      ->check(CLI::Range(0.0f, 1000.0f));
  cmd->add_option_function<float>(
         "--zero-parallax", [&o](float v) { o.zero_parallax_distance = v; },
         "View depth of the zero-parallax plane (default: the scene's)")
      ->check(CLI::Range(1e-4f, 1e6f));
  cmd->add_option("--threads", o.threads,
                  "Threads of the frame schedule (0: one per core); the frames are the same")
      ->check(CLI::Range(0, 1024));
}

}  // namespace pyro::cli
