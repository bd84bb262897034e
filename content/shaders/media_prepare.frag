#version 450 core
// Explosion media at layer size, before the full-size pass (Umenhoffer et al. 2006, section 4):
// dust, then fire, then smoke composited over each other (premultiplied "over": the result over
// the scene equals the three composited in turn), and 1/z of the view depth z each layer texel
// was rendered against (the full-size depth at its representative pixel floor((t + 1/2) s), as
// the spherical-billboard shader fetched it) with the fire's opacity, and the heat shimmer's scene
// offset (fire opacity times the shimmer noise at this texel), so the full-size pass reads them
// in one fetch.
//
// EDGES (depth-aware upsampling): the 1/z is stored negative at texels on a depth edge the
// particles can see, for compose_tiles.comp to find in one gather per 2 x 2 texels: along x or y
// the second difference of the texels' 1/z exceeds u_depth_tolerance times this texel's 1/z (u is
// affine on a plane, so a slope is no edge however steep; a silhouette is a jump), and the three
// texels' clip depths (1/z clamped to the depths the particles reach here, systems/composite/
// particle_depth_grid.h) differ by more than u_depth_tolerance times that range, compose.frag's
// own test (a horizon behind the particles clamps alike).
#ifndef EDGES
#define EDGES 0
#endif
layout(binding = 0) uniform sampler2D u_media;  // dust, smoke, fire cells side by side
uniform int u_cell_width;
layout(binding = 3) uniform sampler2D u_scene_depth;  // full size, window depth
uniform vec2 u_scale;  // full-size pixels per layer texel
uniform float u_near;
uniform float u_far;
layout(binding = 4) uniform sampler2D u_shimmer_noise;  // compose.frag says what it is
uniform float u_shimmer;         // scene offset (fraction of the view) per unit fire opacity
uniform float u_shimmer_tiling;  // noise periods across the view

#if EDGES
layout(binding = 5) uniform sampler2D u_particle_depths;  // compose.frag says what they are
uniform int u_depth_cell;  // their cells' size in pixels
uniform float u_depth_tolerance;
#endif

layout(location = 0) out vec4 o_combined;
layout(location = 1) out vec4 o_depth_fire;

// 1/z at layer texel t's representative pixel (t clamped to the layer).
float inverse_view_depth(ivec2 t) {
  ivec2 layer = ivec2(u_cell_width, textureSize(u_media, 0).y);
  t = clamp(t, ivec2(0), layer - 1);
  ivec2 at = min(ivec2((vec2(t) + 0.5) * u_scale), textureSize(u_scene_depth, 0) - 1);
  float z_ndc = texelFetch(u_scene_depth, at, 0).r * 2.0 - 1.0;
  return (u_far + u_near - z_ndc * (u_far - u_near)) / (2.0 * u_near * u_far);
}

#if EDGES
bool on_edge(ivec2 t, float u) {
  vec2 a = vec2(inverse_view_depth(t - ivec2(1, 0)), inverse_view_depth(t - ivec2(0, 1)));
  vec2 b = vec2(inverse_view_depth(t + ivec2(1, 0)), inverse_view_depth(t + ivec2(0, 1)));
  vec2 second = abs(a + b - 2.0 * u);
  ivec2 cell = ivec2((vec2(t) + 0.5) * u_scale) / u_depth_cell;
  vec2 range = texelFetch(u_particle_depths, cell, 0).rg;  // 1/z: far, near
  vec2 ca = clamp(a, range.x, range.y), cb = clamp(b, range.x, range.y);
  float cu = clamp(u, range.x, range.y);
  vec2 apart = max(abs(ca - cu), abs(cb - cu));
  float seen = u_depth_tolerance * (range.y - range.x);
  return (second.x > u_depth_tolerance * u && apart.x > seen) ||
         (second.y > u_depth_tolerance * u && apart.y > seen);
}
#endif

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 d = texelFetch(u_media, t, 0);
  vec4 s = texelFetch(u_media, t + ivec2(u_cell_width, 0), 0);
  vec4 f = texelFetch(u_media, t + ivec2(2 * u_cell_width, 0), 0);
  o_combined = s + (f + d * (1.0 - f.a)) * (1.0 - s.a);
  float inverse_view = inverse_view_depth(t);
#if EDGES
  if (on_edge(t, inverse_view)) inverse_view = -inverse_view;
#endif
  vec2 uv = (vec2(t) + 0.5) / vec2(u_cell_width, textureSize(u_media, 0).y);
  vec2 noise = textureLod(u_shimmer_noise, uv * u_shimmer_tiling, 0.0).rg * 2.0 - 1.0;
  vec2 offset = noise * (u_shimmer * f.a);
  o_depth_fire = vec4(inverse_view, f.a, offset);
}
