#version 450 core
// The final pass. Per eye: the scene (opaque geometry, and particles when drawn at full
// resolution) with the reduced-resolution particle layer, if any, upsampled bilinearly and
// composited over it (premultiplied "over"); or, for explosions, the media layers (Umenhoffer et
// al. 2006, section 4) upsampled depth-aware and composited over the scene, whose lookup the
// fire distorts (heat shimmer). Then the output is L * left + R * right, clamped, on linear
// values (engine/math/anaglyph.h gives the matrices: identity/zero for a single view, Dubois or
// colour/half-colour for anaglyphs). The target is sRGB: with SRGB_ENCODE the shader encodes
// (GL_FRAMEBUFFER_SRGB off: cheaper on llvmpipe), else GL does (or the target is linear).
//
// Variants (defines from systems/composite/compositor.cpp; on llvmpipe a branch on a uniform
// runs both sides, fetches included, so what is off is compiled out):
//   USE_LEFT, USE_RIGHT  which views this draw reads (a side-by-side half reads one);
//   LAYERS               a reduced-resolution particle layer per view;
//   MEDIA                explosion media instead (DEPTH_AWARE: nearest-depth upsampling at
//                        depth edges, else bilinear; SHIMMER: heat shimmer).
#ifndef USE_LEFT
#define USE_LEFT 1
#endif
#ifndef USE_RIGHT
#define USE_RIGHT 0
#endif
#ifndef LAYERS
#define LAYERS 0
#endif
#ifndef MEDIA
#define MEDIA 0
#endif
#ifndef DEPTH_AWARE
#define DEPTH_AWARE 0
#endif
#ifndef SHIMMER
#define SHIMMER 0
#endif
#ifndef SRGB_ENCODE
#define SRGB_ENCODE 0
#endif
#if SRGB_ENCODE
#include "srgb_encode.glsl"
#endif

layout(binding = 0) uniform sampler2D u_left;
layout(binding = 1) uniform sampler2D u_right;
layout(binding = 2) uniform sampler2D u_left_layer;
layout(binding = 3) uniform sampler2D u_right_layer;
layout(binding = 4) uniform sampler2D u_left_depth;
layout(binding = 5) uniform sampler2D u_right_depth;
layout(binding = 6) uniform sampler2D u_left_media;        // media_prepare.frag: composited
layout(binding = 7) uniform sampler2D u_left_media_depth;  // view depth, fire opacity, shimmer offset
layout(binding = 9) uniform sampler2D u_right_media;
layout(binding = 10) uniform sampler2D u_right_media_depth;
// The shimmer's noise at this frame's time: a slice of engine/math/detail_noise.h's periodic
// volume taken on the CPU (two channels: the x and y offsets), repeating; media_prepare.frag
// multiplies it by the fire's opacity and u_shimmer at layer size into media_depth.ba.
uniform float u_depth_tolerance;  // relative view-depth spread below which bilinear is kept
uniform float u_near;
uniform float u_far;
uniform mat3 u_left_matrix;
uniform mat3 u_right_matrix;
uniform ivec2 u_origin;  // the viewport's lower-left corner in the output: views map 1:1
uniform vec2 u_view_size;

layout(location = 0) out vec4 o_color;

#if MEDIA
float view_depth(float window_depth) {
  float z_ndc = window_depth * 2.0 - 1.0;
  return 2.0 * u_near * u_far / (u_far + u_near - z_ndc * (u_far - u_near));
}

// Nearest-depth upsampling (no halos at depth edges): the four layer texels around this pixel
// were rendered against the view depths in media_depth. Where this pixel's depth agrees (within
// u_depth_tolerance of it) with those four depths interpolated bilinearly to this pixel, the
// pixel lies on the surface the texels saw — a slope included, whose texels' depths differ —
// and the layer is sampled bilinearly by the texture unit; otherwise (a depth edge runs between
// the texels) the texel whose depth is nearest is taken. textureGather returns the four texels
// bilinear filtering would use, as (i0, j1), (i1, j1), (i1, j0), (i0, j0).
vec4 upsampled_media(sampler2D depth, sampler2D media, sampler2D media_depth, ivec2 texel, vec2 uv) {
  vec4 bilinear = textureLod(media, uv, 0.0);
#if DEPTH_AWARE
  vec4 g = textureGather(media_depth, uv, 0);
  float z = view_depth(texelFetch(depth, texel, 0).r);
  vec2 size = vec2(textureSize(media, 0));
  vec2 at = uv * size - 0.5;
  vec2 f = fract(at);
  float interpolated = mix(mix(g.w, g.z, f.x), mix(g.x, g.y, f.x), f.y);
  vec4 diff = abs(g - vec4(z));
  ivec2 i0 = ivec2(floor(at));
  ivec2 pick = diff.w <= diff.z ? i0 : i0 + ivec2(1, 0);
  float best = min(diff.w, diff.z);
  if (diff.x < best) { pick = i0 + ivec2(0, 1); best = diff.x; }
  if (diff.y < best) pick = i0 + ivec2(1, 1);
  vec4 nearest = texelFetch(media, clamp(pick, ivec2(0), ivec2(size) - 1), 0);
  bool agree = abs(interpolated - z) <= u_depth_tolerance * z;
  return agree ? bilinear : nearest;
#else
  return bilinear;
#endif
}

vec3 view_color(sampler2D scene, sampler2D depth, sampler2D media, sampler2D media_depth,
                ivec2 texel, vec2 uv) {
  vec4 m = upsampled_media(depth, media, media_depth, texel, uv);
#if SHIMMER
  // Heat shimmer: the scene seen through hot gas moves along a noise field, by an amount that
  // grows with the fire's opacity here.
  vec2 offset = textureLod(media_depth, uv, 0.0).ba;
  vec3 c = textureLod(scene, uv + offset, 0.0).rgb;
#else
  vec3 c = texelFetch(scene, texel, 0).rgb;
#endif
  return c * (1.0 - m.a) + m.rgb;
}
#else
vec3 view_color(sampler2D scene, sampler2D layer, ivec2 texel, vec2 uv) {
  vec3 c = texelFetch(scene, texel, 0).rgb;
#if LAYERS
  vec4 p = textureLod(layer, uv, 0.0);
  c = c * (1.0 - p.a) + p.rgb;
#endif
  return c;
}
#endif

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy) - u_origin;
  vec2 uv = (vec2(texel) + 0.5) / u_view_size;
  vec3 c = vec3(0.0);
#if MEDIA
#if USE_LEFT
  c += u_left_matrix * view_color(u_left, u_left_depth, u_left_media, u_left_media_depth, texel, uv);
#endif
#if USE_RIGHT
  c += u_right_matrix * view_color(u_right, u_right_depth, u_right_media, u_right_media_depth, texel, uv);
#endif
#else
#if USE_LEFT
  c += u_left_matrix * view_color(u_left, u_left_layer, texel, uv);
#endif
#if USE_RIGHT
  c += u_right_matrix * view_color(u_right, u_right_layer, texel, uv);
#endif
#endif
  c = clamp(c, 0.0, 1.0);
#if SRGB_ENCODE
  c = srgb_encode(c);
#endif
  o_color = vec4(c, 1.0);
}
