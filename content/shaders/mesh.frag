#version 450 core
// Lambertian surface under the scene's lights (lights.glsl): every directional light plus the
// ambient term, in linear RGB. With u_shadowed, the key light is dimmed by the particle media's
// transmittance exp(-tau), tau read from the light phase's opacity shadow map (systems/shadowing/
// opacity_shadow_map.h), trilinearly; with u_mesh_shadowed, also by the meshes' own shadow
// (systems/shadowing/mesh_shadow_map.h): the depth test z - bias <= the casters' depth, filtered
// over the four nearest texels by GL, the bias one texel's depth plus its slope (tan theta) across
// a texel, so that a caster does not shadow its own lit faces.
// FIRE_LIGHTS n (n > 0): the explosion's n fire lights light it too (components/fire_lights.h):
// point sources of intensity I, irradiance I cos(theta) / max(D^2, r^2), reflected as albedo / pi
// (a define, so the loop unrolls with constant indices: on llvmpipe a uniform count costs more).
// SRGB_ENCODE 1: the target is sRGB and GL's conversion is off (systems/mesh_render/
// mesh_renderer.cpp): the shader writes the encoded value.
#ifndef SRGB_ENCODE
#define SRGB_ENCODE 0
#endif
#ifndef FIRE_LIGHTS
#define FIRE_LIGHTS 0
#endif
#if SRGB_ENCODE
#include "srgb_encode.glsl"
#endif
in vec3 v_normal;
in vec3 v_world;

#include "lights.glsl"
uniform vec3 u_albedo;
uniform int u_shadowed;
uniform sampler3D u_shadow_map;    // optical depth toward the light
uniform mat4 u_world_to_shadow;    // world position -> the map's texture coordinates
uniform int u_mesh_shadowed;
uniform sampler2DShadow u_mesh_shadow;    // the casters' depth along the light
uniform mat4 u_mesh_shadow_transform;     // world position -> its texture coordinates and depth
uniform float u_mesh_shadow_texel_depth;  // a texel's side in its depth units

layout(location = 0) out vec4 o_color;

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 direct = vec3(0.0);
  for (int i = 0; i < sun_count(); ++i) {
    float lambert = max(dot(n, toward_sun(i)), 0.0);
    if (i == 0 && u_shadowed != 0)
      lambert *= exp(-texture(u_shadow_map, (u_world_to_shadow * vec4(v_world, 1.0)).xyz).r);
    if (i == 0 && u_mesh_shadowed != 0 && lambert > 0.0) {
      float cosine = dot(n, toward_sun(i));
      float slope = min(sqrt(max(1.0 - cosine * cosine, 0.0)) / max(cosine, 1e-3), 8.0);
      vec3 t = (u_mesh_shadow_transform * vec4(v_world, 1.0)).xyz;
      lambert *= textureLod(u_mesh_shadow, vec3(t.xy, t.z - (1.0 + slope) * u_mesh_shadow_texel_depth), 0.0);
    }
    direct += sun_radiance(i) * lambert;
  }
  vec3 c = u_albedo * (ambient_light() + direct);
#if FIRE_LIGHTS
  {
    vec3 fire = vec3(0.0);
    for (int j = 0; j < FIRE_LIGHTS; ++j) {
      FireLightPath path = fire_light_path(j, v_world);
      fire += fire_light(j, path, max(-fire_light_cosine(path, n), 0.0));
    }
    c += u_albedo * fire * (1.0 / 3.14159265358979);
  }
#endif
#if SRGB_ENCODE
  c = srgb_encode(c);
#endif
  o_color = vec4(c, 1.0);
}
