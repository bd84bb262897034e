// "shadows": lit media, and how the splats scatter the sun.
#include "components/fire_lights.h"
#include "components/shadow_settings.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& scattering_keys() {
  static const SunScattering d{};
  static const ParameterTable table{
      "shadows.scattering", "How Gaussian splats scatter the sun towards the eye.",
      {number_key("anisotropy", Range{-0.99, 0.99}, "Henyey-Greenstein g; positive scatters forward.")
           .with_default(static_cast<float>(d.anisotropy)),
       integer_key("octaves", 1, 16, "Octaves of multiple scattering; 1 is single scattering.")
           .with_default(d.octaves.octaves),
       number_key("attenuation", Range{0.0, 1.0, true, false}, "Octave i scales the optical depth by a^i.")
           .with_default(static_cast<float>(d.octaves.attenuation)),
       number_key("contribution", kUnit, "Octave i adds b^i of the sun's light.")
           .with_default(static_cast<float>(d.octaves.contribution)),
       number_key("eccentricity", kUnit, "Octave i scales the lobe's g by c^i.")
           .with_default(static_cast<float>(d.octaves.eccentricity))}};
  return table;
}

const ParameterTable& shadow_keys() {
  static const ShadowSettings d{};
  static const ParameterTable table{
      "shadows", "Lit particle media that shadow themselves and the ground.",
      {enum_key<ShadowMethod>("method", "Exact shadow rays, an opacity shadow map, or none (unshadowed).")
           .with_default(d.method),
       integer_key("map_size", 4, 2048, "The opacity shadow map's texels across the light.")
           .with_default(d.map_size),
       integer_key("map_slices", 4, 1024, "The map's slices along the light.").with_default(d.map_slices),
       integer_key("mesh_map_size", 16, 8192, "Texels across the light of the meshes' shadow map.")
           .with_default(d.mesh_map_size),
       enum_key<SplatSunlight>("splat_sunlight",
                               "Gaussian splats' sunlight at each fragment, or interpolated from each "
                               "billboard's corners (cheaper).")
           .with_default(d.splat_sunlight),
       integer_key("fire_lights", 0, kMaxFireLights, "Point lights clustered from the fire; 0: none.")
           .with_default(d.fire_lights),
       object_key("scattering", scattering_keys(), "How the splats scatter the sun.")}};
  return table;
}

}  // namespace pyro
