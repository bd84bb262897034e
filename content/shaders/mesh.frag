#version 450 core
// Lambertian surface under one directional light plus ambient light, in linear RGB.
// SRGB_ENCODE 1: the target is sRGB and GL's conversion is off (systems/mesh_render/
// mesh_renderer.cpp): the shader writes the encoded value.
#ifndef SRGB_ENCODE
#define SRGB_ENCODE 0
#endif
#if SRGB_ENCODE
#include "srgb_encode.glsl"
#endif
in vec3 v_normal;

uniform vec3 u_albedo;
uniform vec3 u_light_direction;  // unit, the direction light travels
uniform vec3 u_light_color;
uniform vec3 u_ambient;

layout(location = 0) out vec4 o_color;

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float lambert = max(dot(n, -u_light_direction), 0.0);
  vec3 c = u_albedo * (u_ambient + u_light_color * lambert);
#if SRGB_ENCODE
  c = srgb_encode(c);
#endif
  o_color = vec4(c, 1.0);
}
