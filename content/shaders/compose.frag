#version 450 core
// The final pass. Per eye: the scene (opaque geometry, and particles when drawn at full
// resolution) with the reduced-resolution particle layer, if any, upsampled bilinearly and
// composited over it (premultiplied "over"); or, for explosions, the media layers (Umenhoffer et
// al. 2006, section 4) upsampled (depth-aware or bilinear) and composited over the scene, whose
// lookup the fire distorts (heat shimmer). Then the output is L * left + R * right on linear
// values (engine/math/anaglyph.h gives the matrices: identity/zero for a single view, Dubois or
// colour/half-colour for anaglyphs), its highlights rolled off without a hue shift
// (highlight_rolloff.glsl). The target is sRGB: with SRGB_ENCODE the shader
// encodes (GL_FRAMEBUFFER_SRGB off: cheaper on llvmpipe), else GL does (or the target is linear).
//
// Variants (defines from systems/composite/compositor.cpp; on llvmpipe a branch on a uniform
// runs both sides, fetches included, so what is off is compiled out):
//   USE_LEFT, USE_RIGHT  which views this draw reads (a side-by-side half reads one);
//   LAYERS               a reduced-resolution particle layer per view;
//   MEDIA                explosion media instead (FULL_SIZE: layers at the view's size, read
//                        texel for texel; else DEPTH_AWARE: upsampled_media below, FRONT:
//                        bilinear but no media on a surface nearer than every particle, or
//                        bilinear;
//                        SHIMMER: heat shimmer);
//   TRANSPARENT          alpha out: the coverage of the scene (its alpha: the meshes', and the
//                        particles' drawn into it) and of the layer over it, composited as the
//                        colours are ("over": a = a_scene (1 - a_layer) + a_layer), the larger of
//                        the two views' where a draw reads both; else alpha 1. The colours are
//                        the same in both: the background is in the scene's colour either way.
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
#ifndef FRONT
#define FRONT 0
#endif
#ifndef FULL_SIZE
#define FULL_SIZE 0
#endif
#ifndef SRGB_ENCODE
#define SRGB_ENCODE 0
#endif
#ifndef TRANSPARENT
#define TRANSPARENT 0
#endif
#if SRGB_ENCODE
#include "srgb_encode.glsl"
#endif
#include "highlight_rolloff.glsl"

layout(binding = 0) uniform sampler2D u_left;
layout(binding = 1) uniform sampler2D u_right;
layout(binding = 2) uniform sampler2D u_left_layer;
layout(binding = 3) uniform sampler2D u_right_layer;
layout(binding = 4) uniform sampler2D u_left_depth;
layout(binding = 5) uniform sampler2D u_right_depth;
layout(binding = 6) uniform sampler2D u_left_media;        // media_prepare.frag: composited
layout(binding = 7) uniform sampler2D u_left_media_depth;  // 1/z, fire opacity, shimmer offset
layout(binding = 9) uniform sampler2D u_right_media;
layout(binding = 10) uniform sampler2D u_right_media_depth;
// Per u_depth_cell-pixel cell of the view, 1/z at the far and the near end of the view depths z
// its particles reach (systems/composite/particle_depth_grid.h): depths that clamp alike to them
// give a texel the same media.
layout(binding = 11) uniform sampler2D u_left_particle_depths;
layout(binding = 12) uniform sampler2D u_right_particle_depths;
uniform int u_depth_cell;
// The shimmer's noise at this frame's time: a slice of engine/math/detail_noise.h's periodic
// volume taken on the CPU (two channels: the x and y offsets), repeating; media_prepare.frag
// multiplies it by the fire's opacity and u_shimmer at layer size into media_depth.ba.
uniform float u_depth_tolerance;  // clip depths closer (share of their extent): bilinear
#include "inverse_depth.glsl"
uniform mat3 u_left_matrix;
uniform mat3 u_right_matrix;
uniform ivec2 u_origin;  // the viewport's lower-left corner in the output: views map 1:1
uniform vec2 u_view_size;

layout(location = 0) out vec4 o_color;

#if MEDIA
#if FRONT
// Whether this pixel's surface is nearer than every particle around it (u above the near end of
// the particles' depths in its cell): then no particle lies in front of it and its media is 0,
// exactly (the spherical billboard's path ends at the surface, Umenhoffer et al. eq. 2).
bool nearer_than_every_particle(sampler2D depth, sampler2D particle_depths, ivec2 texel) {
  float u = inverse_depth(texelFetch(depth, texel, 0).r);
  return u > texelFetch(particle_depths, texel / u_depth_cell, 0).g;
}
#endif

#if DEPTH_AWARE
float max4(vec4 v) { return max(max(v.x, v.y), max(v.z, v.w)); }

// The slope of u = 1/z at this pixel along `step`: the smaller of the two one-sided differences
// (the other may cross a silhouette), or the one inside the view at its border; 0 at an extremum
// (a gap between two bars, or a bar, one pixel wide: both differences cross an edge).
float slope(sampler2D depth, ivec2 texel, ivec2 step, float u, int at, int last) {
  float before = inverse_depth(texelFetch(depth, max(texel - step, ivec2(0)), 0).r);
  float after = inverse_depth(texelFetch(depth, min(texel + step, ivec2(u_view_size) - 1), 0).r);
  float back = at > 0 ? u - before : after - u;
  float ahead = at < last ? after - u : u - before;
  return back * ahead <= 0.0 ? 0.0 : abs(back) < abs(ahead) ? back : ahead;
}

// Depth-aware upsampling: joint bilateral upsampling (Kopf et al. 2007, eq. 2) with the bilinear
// tent as the spatial filter and the layer's clip depths as the guide, gated so that it is the
// texture unit's bilinear sample wherever the four texels it would use saw what this pixel sees.
//
// The four texels (textureGather's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0)) hold particles
// clipped against the full-size depth at their representative pixels floor((t + 1/2) S) (S
// pixels per texel; media_prepare.frag). On a plane u = 1/z is affine in screen position, so
// this pixel's u and slope (one-sided differences of the full-size depth, slope()) predict each
// texel's u exactly if it lies on the same plane. Prediction and texel are compared as clip
// depths: clamped to the depths the particles around this pixel reach (u_left_particle_depths;
// depths that clamp alike give a texel the same media, so a horizon behind the explosion, or a
// tower's bars with the smoke in front of them, is no edge), their difference r in units of
// that range's extent (the share of the particles' depths between them).
//   Every texel within u_depth_tolerance: bilinear. This covers a slope however steep, a curved
//   surface, and any depth edge the particles do not reach into.
//   Else the bilinear weights are multiplied by exp(-(r / rho)^4) + kappa and renormalised: the
//   texels that saw this pixel's surface keep their shares, those whose particles were clipped
//   against another surface, across an edge, drop out (no halo, and unlike the nearest-depth
//   upsampling of Cantlay 2007, GPU Gems 3 ch. 23, no blocks of a single texel). rho = 0.5: a
//   texel whose clip depth differs by the particles' whole extent keeps e^-16 of its share, one
//   differing by a quarter of it 94%: such a difference changes the media less than leaving the
//   texel out would (measured on the explosion). kappa = 1e-4: where no texel saw the surface
//   (a bar, or a gap between bars, thinner than a texel), the texels keep their bilinear shares,
//   the best guess left.
// Before both: a pixel nearer_than_every_particle has no media. That removes the halo that
// geometry thinner than a texel, which no texel saw, would carry (media_edges.frag marks its
// tiles, and the FRONT variant does the same there).
vec4 upsampled_media(sampler2D depth, sampler2D media, sampler2D media_depth,
                     sampler2D particle_depths, ivec2 texel, vec2 uv) {
  vec4 bilinear = textureLod(media, uv, 0.0);
  ivec2 size = textureSize(media, 0);
  vec2 s = u_view_size / vec2(size);
  vec2 at = uv * vec2(size) - 0.5;
  vec2 i0 = floor(at);
  vec2 f = at - i0;
  float u = inverse_depth(texelFetch(depth, texel, 0).r);
  ivec2 last = ivec2(u_view_size) - 1;
  vec2 g = vec2(slope(depth, texel, ivec2(1, 0), u, texel.x, last.x),
                slope(depth, texel, ivec2(0, 1), u, texel.y, last.y));
  // The texels' representative pixel centres from this one, their indices clamped as the
  // sampler clamps them.
  vec2 lo = clamp(i0, vec2(0.0), vec2(size - 1)), hi = clamp(i0 + 1.0, vec2(0.0), vec2(size - 1));
  vec2 p0 = floor((lo + 0.5) * s) + 0.5 - (vec2(texel) + 0.5);
  vec2 p1 = floor((hi + 0.5) * s) + 0.5 - (vec2(texel) + 0.5);
  vec4 predicted = u + g.x * vec4(p0.x, p1.x, p1.x, p0.x) + g.y * vec4(p1.y, p1.y, p0.y, p0.y);
  // Clip depths, clamped in 1/z (a prediction beyond the horizon, u <= 0, clamps to the far end).
  vec2 range = texelFetch(particle_depths, texel / u_depth_cell, 0).rg;  // 1/z: far, near
  float extent = max(range.y - range.x, 1e-30);  // 0 where no particle reaches: r = 0
  vec4 texel_u = textureGather(media_depth, uv, 0);
  vec4 r = abs(clamp(texel_u, range.x, range.y) - clamp(predicted, range.x, range.y)) / extent;
  const float rho = 0.5, kappa = 1e-4;
  vec4 b = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  vec4 q = r * r / (rho * rho);
  vec4 w = b * (exp(-q * q) + kappa);
  w /= dot(w, vec4(1.0));
  // The four texels whole (four fetches, where a gather per channel reads sixteen).
  ivec2 t0 = ivec2(lo), t1 = ivec2(hi);
  vec4 weighted = w.x * texelFetch(media, ivec2(t0.x, t1.y), 0) +
                  w.y * texelFetch(media, t1, 0) + w.z * texelFetch(media, ivec2(t1.x, t0.y), 0) +
                  w.w * texelFetch(media, t0, 0);
  if (u > range.y) return vec4(0.0);  // nearer_than_every_particle
  return max4(r) <= u_depth_tolerance ? bilinear : weighted;
}
#endif

vec4 layer_media(sampler2D depth, sampler2D media, sampler2D media_depth,
                 sampler2D particle_depths, ivec2 texel, vec2 uv) {
#if FULL_SIZE
  return texelFetch(media, texel, 0);  // a texel per pixel: nothing to upsample
#elif DEPTH_AWARE
  return upsampled_media(depth, media, media_depth, particle_depths, texel, uv);
#elif FRONT
  return nearer_than_every_particle(depth, particle_depths, texel) ? vec4(0.0)
                                                                   : textureLod(media, uv, 0.0);
#else
  return textureLod(media, uv, 0.0);
#endif
}

vec3 view_color(sampler2D scene, sampler2D depth, sampler2D media, sampler2D media_depth,
                sampler2D particle_depths, ivec2 texel, vec2 uv, out float alpha) {
  vec4 m = layer_media(depth, media, media_depth, particle_depths, texel, uv);
#if SHIMMER
  // Heat shimmer: the scene seen through hot gas moves along a noise field, by an amount that
  // grows with the fire's opacity here.
#if FULL_SIZE
  vec2 offset = texelFetch(media_depth, texel, 0).ba;
#else
  vec2 offset = textureLod(media_depth, uv, 0.0).ba;
#endif
  vec4 s = textureLod(scene, uv + offset, 0.0);
#else
  vec4 s = texelFetch(scene, texel, 0);
#endif
  vec3 c = s.rgb;
  alpha = s.a * (1.0 - m.a) + m.a;
  return c * (1.0 - m.a) + m.rgb;
}
#else
vec3 view_color(sampler2D scene, sampler2D layer, ivec2 texel, vec2 uv, out float alpha) {
  vec4 s = texelFetch(scene, texel, 0);
  vec3 c = s.rgb;
  alpha = s.a;
#if LAYERS
  vec4 p = textureLod(layer, uv, 0.0);
  c = c * (1.0 - p.a) + p.rgb;
  alpha = alpha * (1.0 - p.a) + p.a;
#endif
  return c;
}
#endif

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy) - u_origin;
  vec2 uv = (vec2(texel) + 0.5) / u_view_size;
  vec3 c = vec3(0.0);
  float a = 0.0, a_view = 0.0;
#if MEDIA
#if USE_LEFT
  c += u_left_matrix * view_color(u_left, u_left_depth, u_left_media, u_left_media_depth,
                                  u_left_particle_depths, texel, uv, a_view);
  a = max(a, a_view);
#endif
#if USE_RIGHT
  c += u_right_matrix * view_color(u_right, u_right_depth, u_right_media, u_right_media_depth,
                                   u_right_particle_depths, texel, uv, a_view);
  a = max(a, a_view);
#endif
#else
#if USE_LEFT
  c += u_left_matrix * view_color(u_left, u_left_layer, texel, uv, a_view);
  a = max(a, a_view);
#endif
#if USE_RIGHT
  c += u_right_matrix * view_color(u_right, u_right_layer, texel, uv, a_view);
  a = max(a, a_view);
#endif
#endif
  c = roll_off_highlights(c);
#if SRGB_ENCODE
  c = srgb_encode(c);
#endif
#if TRANSPARENT
  o_color = vec4(c, a);
#else
  o_color = vec4(c, 1.0);
#endif
}
