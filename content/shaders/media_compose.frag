#version 450 core
// The final pass for explosion media (Umenhoffer et al. 2006, section 4). A separate program
// from stereo_compose.frag: on llvmpipe the larger shader slows every pixel even when its
// media branch is off, and most frames have no media.
// The final pass. Per eye: the scene (opaque geometry, and particles when drawn at full
// resolution) with the reduced-resolution particle layer, if any, upsampled bilinearly and
// composited over it (premultiplied "over"). Then the output is L * left + R * right, clamped,
// on linear values (engine/math/anaglyph.h gives the matrices: identity/zero for a single view,
// Dubois or colour/half-colour for anaglyphs). The target is sRGB: GL encodes.
layout(binding = 0) uniform sampler2D u_left;
layout(binding = 1) uniform sampler2D u_right;
layout(binding = 2) uniform sampler2D u_left_layer;
layout(binding = 3) uniform sampler2D u_right_layer;
uniform int u_has_layers;
// Explosion media (Umenhoffer et al. 2006, section 4): per eye, dust, fire and smoke layers at a
// fraction of the view, upsampled depth-aware against the full-resolution scene depth and
// composited in that order over the scene, whose lookup the fire layer distorts (heat shimmer).
layout(binding = 4) uniform sampler2D u_left_depth;
layout(binding = 5) uniform sampler2D u_right_depth;
layout(binding = 6) uniform sampler2D u_left_dust;
layout(binding = 7) uniform sampler2D u_left_smoke;
layout(binding = 8) uniform sampler2D u_left_fire;
layout(binding = 9) uniform sampler2D u_right_dust;
layout(binding = 10) uniform sampler2D u_right_smoke;
layout(binding = 11) uniform sampler2D u_right_fire;
layout(binding = 12) uniform sampler3D u_noise;  // engine/math/detail_noise.h, periodic, [0, 1]
uniform int u_has_media;
uniform int u_upsample;          // 0 bilinear, 1 nearest-depth where the depths disagree
uniform float u_depth_tolerance;  // relative view-depth spread below which bilinear is kept
uniform float u_near;
uniform float u_far;
uniform float u_shimmer;         // scene offset (fraction of the view) per unit fire opacity
uniform float u_time;
uniform mat3 u_left_matrix;
uniform mat3 u_right_matrix;
uniform int u_use_left;   // 0 when u_left_matrix is zero: skip the fetches
uniform int u_use_right;
uniform ivec2 u_origin;  // the viewport's lower-left corner in the output: views map 1:1
uniform vec2 u_view_size;

layout(location = 0) out vec4 o_color;

float view_depth(float window_depth) {
  float z_ndc = window_depth * 2.0 - 1.0;
  return 2.0 * u_near * u_far / (u_far + u_near - z_ndc * (u_far - u_near));
}

// Weights of the four layer texels around this pixel (lower-left texel `base`). Bilinear where
// the scene depths those texels were rendered against (the full-resolution depth at the pixel
// the spherical-billboard shader fetched for each: floor((t + 1/2) s)) agree with this pixel's
// depth; otherwise all weight on the texel whose depth is nearest (nearest-depth upsampling), so
// a particle layer does not bleed across a depth edge (no halos).
vec4 upsample_weights(sampler2D depth, vec2 layer_size, ivec2 texel, vec2 uv, out ivec2 base) {
  vec2 f = uv * layer_size - 0.5;
  base = ivec2(floor(f));
  vec2 w = f - vec2(base);
  vec4 bilinear = vec4((1.0 - w.x) * (1.0 - w.y), w.x * (1.0 - w.y), (1.0 - w.x) * w.y, w.x * w.y);
  if (u_upsample == 0) return bilinear;
  float z = view_depth(texelFetch(depth, texel, 0).r);
  vec2 scale = u_view_size / layer_size;
  ivec2 last = ivec2(layer_size) - 1;
  float nearest = 1e30, spread = 0.0;
  int pick = 0;
  for (int k = 0; k < 4; ++k) {
    ivec2 t = clamp(base + ivec2(k & 1, k >> 1), ivec2(0), last);
    ivec2 at = min(ivec2((vec2(t) + 0.5) * scale), ivec2(u_view_size) - 1);
    float diff = abs(view_depth(texelFetch(depth, at, 0).r) - z);
    spread = max(spread, diff);
    if (diff < nearest) { nearest = diff; pick = k; }
  }
  if (spread <= u_depth_tolerance * z) return bilinear;
  vec4 one = vec4(0.0);
  one[pick] = 1.0;
  return one;
}

vec4 fetch_layer(sampler2D layer, ivec2 base, vec4 w) {
  ivec2 last = textureSize(layer, 0) - 1;
  vec4 c = vec4(0.0);
  for (int k = 0; k < 4; ++k)
    if (w[k] > 0.0) c += w[k] * texelFetch(layer, clamp(base + ivec2(k & 1, k >> 1), ivec2(0), last), 0);
  return c;
}

vec3 media_color(sampler2D scene, sampler2D depth, sampler2D dust, sampler2D smoke,
                 sampler2D fire, ivec2 texel, vec2 uv) {
  ivec2 base;
  vec4 w = upsample_weights(depth, vec2(textureSize(dust, 0)), texel, uv, base);
  vec4 f = fetch_layer(fire, base, w);
  // Heat shimmer: the scene seen through hot gas moves along a noise field, by an amount that
  // grows with the fire's opacity here.
  vec2 offset = vec2(0.0);
  if (u_shimmer > 0.0 && f.a > 0.0) {
    vec3 q = vec3(uv * 3.0, u_time);
    offset = (vec2(texture(u_noise, q).r, texture(u_noise, q + vec3(0.5, 0.25, 0.5)).r) * 2.0 - 1.0)
             * u_shimmer * f.a;
  }
  vec3 c = offset == vec2(0.0) ? texelFetch(scene, texel, 0).rgb : textureLod(scene, uv + offset, 0.0).rgb;
  vec4 d = fetch_layer(dust, base, w);
  c = c * (1.0 - d.a) + d.rgb;
  c = c * (1.0 - f.a) + f.rgb;
  vec4 s = fetch_layer(smoke, base, w);
  return c * (1.0 - s.a) + s.rgb;
}

vec3 eye_color(sampler2D scene, sampler2D layer, ivec2 texel, vec2 uv) {
  vec3 c = texelFetch(scene, texel, 0).rgb;
  if (u_has_layers != 0) {
    vec4 p = textureLod(layer, uv, 0.0);
    c = c * (1.0 - p.a) + p.rgb;
  }
  return c;
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy) - u_origin;
  vec2 uv = (vec2(texel) + 0.5) / u_view_size;
  vec3 c = vec3(0.0);
  if (u_has_media != 0) {
    if (u_use_left != 0)
      c += u_left_matrix * media_color(u_left, u_left_depth, u_left_dust, u_left_smoke, u_left_fire, texel, uv);
    if (u_use_right != 0)
      c += u_right_matrix * media_color(u_right, u_right_depth, u_right_dust, u_right_smoke, u_right_fire, texel, uv);
  } else {
    if (u_use_left != 0) c += u_left_matrix * eye_color(u_left, u_left_layer, texel, uv);
    if (u_use_right != 0) c += u_right_matrix * eye_color(u_right, u_right_layer, texel, uv);
  }
  o_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
