#pragma once
// Resource: how the light phase lights the particle media (docs/lighting.md). Present only in a
// world whose scene has a "shadows" block; without it the media are shaded as before lighting
// existed (the splats' colours as given, the explosion's dust and smoke shadowed by themselves
// alone). With it the particles' colours are albedos, and each fragment is lit by the sun's colour
// times the sun's transmittance there, plus the ambient light.
#include <cstdint>

#include "engine/core/enum_names.h"
#include "engine/math/scattering_octaves.h"

namespace pyro {

// How the sun's transmittance to each particle (and to the opaque surfaces) is found.
enum class ShadowMethod : uint8_t {
  none,        // lit, unshadowed: transmittance 1 everywhere (what shadows save, in the charts)
  shadow_map,  // opacity shadow map (Kim & Neumann 2001): a light-space grid of optical depths
  rays,        // exact: the closed-form line integrals of the particles along each shadow ray
};
inline constexpr EnumName<ShadowMethod> shadow_method_names[] = {
    {ShadowMethod::none, "none"}, {ShadowMethod::shadow_map, "map"}, {ShadowMethod::rays, "rays"}};
constexpr const auto& enum_names(ShadowMethod) { return shadow_method_names; }

// Where a Gaussian splat's sunlight (its own shadow across it, the others' depth and its slope)
// is evaluated (content/shaders/splat_sunlight.glsl): at each fragment, or at the centre and one
// standard deviation either side along the billboard's axes, as a plane the fragments interpolate
// (a fragment's cost then the unlit one's and an exponential; `pyro chart shadows`,
// docs/lighting.md).
enum class SplatSunlight : uint8_t { fragments, vertices };
inline constexpr EnumName<SplatSunlight> splat_sunlight_names[] = {{SplatSunlight::fragments, "fragments"},
                                                                   {SplatSunlight::vertices, "vertices"}};
constexpr const auto& enum_names(SplatSunlight) { return splat_sunlight_names; }

struct ShadowSettings {
  // The defaults: the cheapest setting within 0.015 of the exact-shadow reference on the shipped
  // clouds and fog (`pyro chart shadows`, docs/lighting.md).
  ShadowMethod method = ShadowMethod::shadow_map;
  // The opacity shadow map: texels across the light on its longer side, and slices along it.
  // The opaque surfaces read it whatever the particles' method.
  int map_size = 64;
  int map_slices = 32;
  // The explosion's fire as light: this many point lights clustered from the fire particles
  // (components/fire_lights.h) light its dust, smoke and the ground; 0: fire lights nothing.
  int fire_lights = 2;
  // How the splats scatter the sun towards the eye: a Henyey–Greenstein lobe and octaves of
  // multiple scattering (engine/math/scattering_octaves.h). The default, one isotropic octave,
  // is single scattering as the reference computes it.
  SunScattering scattering{};
  // The explosion's media only: each fragment's transmittance summed exactly over every particle
  // drawn and its fire light over every fire emitter (O(particles) a fragment;
  // sphere_billboard.frag, LIT 2), whatever `method`: the truth
  // that `pyro bench explosion-shadows` measures the methods against. Not in the scene format.
  bool exact_fragments = false;
  // The meshes' shadow (components/mesh_shadow.h): texels across the light on the grid's longer
  // side, which is fitted to the meshes that cast (not the ground planes).
  int mesh_map_size = 1024;
  // Gaussian splats' sunlight: per fragment, or a plane across each billboard from its corners.
  SplatSunlight splat_sunlight = SplatSunlight::fragments;

  bool operator==(const ShadowSettings&) const = default;
};

}  // namespace pyro
