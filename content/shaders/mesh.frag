#version 450 core
// Lambertian surface under one directional light plus ambient light, in linear RGB. With
// u_shadowed, the light is dimmed by the particle media's transmittance exp(-tau), tau read from
// the light phase's opacity shadow map (systems/shadowing/opacity_shadow_map.h), trilinearly.
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

uniform vec3 u_albedo;
uniform vec3 u_light_direction;  // unit, the direction light travels
uniform vec3 u_light_color;
uniform vec3 u_ambient;
uniform int u_shadowed;
uniform sampler3D u_shadow_map;    // optical depth toward the light
uniform mat4 u_world_to_shadow;    // world position -> the map's texture coordinates
#if FIRE_LIGHTS
uniform vec4 u_fire_lights[FIRE_LIGHTS];     // world position, radius
uniform vec3 u_fire_intensity[FIRE_LIGHTS];
#endif

layout(location = 0) out vec4 o_color;

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float lambert = max(dot(n, -u_light_direction), 0.0);
  if (u_shadowed != 0)
    lambert *= exp(-texture(u_shadow_map, (u_world_to_shadow * vec4(v_world, 1.0)).xyz).r);
  vec3 c = u_albedo * (u_ambient + u_light_color * lambert);
#if FIRE_LIGHTS
  {
    vec3 fire = vec3(0.0);
    for (int j = 0; j < FIRE_LIGHTS; ++j) {
      vec3 to_light = u_fire_lights[j].xyz - v_world;
      float d2 = dot(to_light, to_light);
      float cosine = d2 > 0.0 ? max(dot(n, to_light) * inversesqrt(d2), 0.0) : 0.0;
      fire += u_fire_intensity[j] * cosine / max(d2, u_fire_lights[j].w * u_fire_lights[j].w);
    }
    c += u_albedo * fire * (1.0 / 3.14159265358979);
  }
#endif
#if SRGB_ENCODE
  c = srgb_encode(c);
#endif
  o_color = vec4(c, 1.0);
}
