#pragma once
// Resource: how the light phase lights the particle media (docs/lighting.md). Present only in a
// world whose scene has a "shadows" block; without it the splats keep their colours as given,
// unlit, as before lighting existed. With it each particle's colour is its albedo times the light
// reaching its centre: the sun's colour times the sun's transmittance there, plus the ambient light.
#include <cstdint>

#include "engine/core/enum_names.h"

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

struct ShadowSettings {
  // The defaults: the cheapest setting within 0.015 of the exact-shadow reference on the shipped
  // clouds and fog (`pyro chart shadows`, docs/lighting.md).
  ShadowMethod method = ShadowMethod::shadow_map;
  // The opacity shadow map: texels across the light on its longer side, and slices along it.
  // The opaque surfaces read it whatever the particles' method.
  int map_size = 64;
  int map_slices = 32;

  bool operator==(const ShadowSettings&) const = default;
};

}  // namespace pyro
