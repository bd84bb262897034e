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

// Nearest-depth upsampling (no halos at depth edges): the four layer texels around this pixel
// were rendered against the full-resolution depth at their representative pixels
// (floor((t + 1/2) s), as the spherical-billboard shader fetched it). Where those depths agree
// with this pixel's (spread within u_depth_tolerance of its view depth) the layers are sampled
// bilinearly by the texture unit; otherwise every layer takes the texel whose depth is nearest.
// Returns true, and that texel, in the second case. Written straight-line: llvmpipe runs loops
// over dynamically indexed vectors several times slower.
bool nearest_depth_texel(sampler2D depth, vec2 layer_size, ivec2 texel, vec2 uv, out ivec2 pick) {
  pick = ivec2(0);
  if (u_upsample == 0) return false;
  vec2 f = uv * layer_size - 0.5;
  ivec2 base = ivec2(floor(f));
  ivec2 last = ivec2(layer_size) - 1;
  vec2 scale = u_view_size / layer_size;
  ivec2 edge = ivec2(u_view_size) - 1;
  ivec2 t0 = clamp(base, ivec2(0), last);
  ivec2 t1 = clamp(base + ivec2(1, 0), ivec2(0), last);
  ivec2 t2 = clamp(base + ivec2(0, 1), ivec2(0), last);
  ivec2 t3 = clamp(base + ivec2(1, 1), ivec2(0), last);
  float z = view_depth(texelFetch(depth, texel, 0).r);
  float d0 = abs(view_depth(texelFetch(depth, min(ivec2((vec2(t0) + 0.5) * scale), edge), 0).r) - z);
  float d1 = abs(view_depth(texelFetch(depth, min(ivec2((vec2(t1) + 0.5) * scale), edge), 0).r) - z);
  float d2 = abs(view_depth(texelFetch(depth, min(ivec2((vec2(t2) + 0.5) * scale), edge), 0).r) - z);
  float d3 = abs(view_depth(texelFetch(depth, min(ivec2((vec2(t3) + 0.5) * scale), edge), 0).r) - z);
  if (max(max(d0, d1), max(d2, d3)) <= u_depth_tolerance * z) return false;
  ivec2 ta = d0 <= d1 ? t0 : t1;
  float da = min(d0, d1);
  ivec2 tb = d2 <= d3 ? t2 : t3;
  float db = min(d2, d3);
  pick = da <= db ? ta : tb;
  return true;
}

vec4 layer_value(sampler2D layer, bool nearest, ivec2 pick, vec2 uv) {
  return nearest ? texelFetch(layer, pick, 0) : textureLod(layer, uv, 0.0);
}

vec3 media_color(sampler2D scene, sampler2D depth, sampler2D dust, sampler2D smoke,
                 sampler2D fire, ivec2 texel, vec2 uv) {
  ivec2 pick;
  bool nearest = nearest_depth_texel(depth, vec2(textureSize(dust, 0)), texel, uv, pick);
  vec4 f = layer_value(fire, nearest, pick, uv);
  // Heat shimmer: the scene seen through hot gas moves along a noise field, by an amount that
  // grows with the fire's opacity here.
  vec2 offset = vec2(0.0);
  if (u_shimmer > 0.0 && f.a > 0.0) {
    vec3 q = vec3(uv * 3.0, u_time);
    offset = (vec2(texture(u_noise, q).r, texture(u_noise, q + vec3(0.5, 0.25, 0.5)).r) * 2.0 - 1.0)
             * u_shimmer * f.a;
  }
  vec3 c = offset == vec2(0.0) ? texelFetch(scene, texel, 0).rgb : textureLod(scene, uv + offset, 0.0).rgb;
  vec4 d = layer_value(dust, nearest, pick, uv);
  c = c * (1.0 - d.a) + d.rgb;
  c = c * (1.0 - f.a) + f.rgb;
  vec4 s = layer_value(smoke, nearest, pick, uv);
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
