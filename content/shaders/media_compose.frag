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
layout(binding = 6) uniform sampler2D u_left_media;        // media_prepare.frag: composited
layout(binding = 7) uniform sampler2D u_left_media_depth;  // view depth, fire opacity
layout(binding = 9) uniform sampler2D u_right_media;
layout(binding = 10) uniform sampler2D u_right_media_depth;
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
// were rendered against the view depths in media_depth. Where those agree with this pixel's
// depth (spread within u_depth_tolerance of it) the layer is sampled bilinearly by the texture
// unit; otherwise the texel whose depth is nearest is taken. textureGather returns the four
// texels bilinear filtering would use, as (i0, j1), (i1, j1), (i1, j0), (i0, j0).
vec4 upsampled_media(sampler2D depth, sampler2D media, sampler2D media_depth, ivec2 texel, vec2 uv) {
  if (u_upsample == 0) return textureLod(media, uv, 0.0);
  vec4 g = textureGather(media_depth, uv, 0);
  float z = view_depth(texelFetch(depth, texel, 0).r);
  vec4 diff = abs(g - vec4(z));
  if (max(max(diff.x, diff.y), max(diff.z, diff.w)) <= u_depth_tolerance * z)
    return textureLod(media, uv, 0.0);
  vec2 size = vec2(textureSize(media, 0));
  ivec2 i0 = ivec2(floor(uv * size - 0.5));
  ivec2 pick = diff.w <= diff.z ? i0 : i0 + ivec2(1, 0);
  float best = min(diff.w, diff.z);
  if (diff.x < best) { pick = i0 + ivec2(0, 1); best = diff.x; }
  if (diff.y < best) pick = i0 + ivec2(1, 1);
  return texelFetch(media, clamp(pick, ivec2(0), ivec2(size) - 1), 0);
}

vec3 media_color(sampler2D scene, sampler2D depth, sampler2D media, sampler2D media_depth,
                 ivec2 texel, vec2 uv) {
  vec4 m = upsampled_media(depth, media, media_depth, texel, uv);
  // Heat shimmer: the scene seen through hot gas moves along a noise field, by an amount that
  // grows with the fire's opacity here.
  vec2 offset = vec2(0.0);
  if (u_shimmer > 0.0 && m.a > 0.0) {
    float fire = textureLod(media_depth, uv, 0.0).g;
    if (fire > 0.0) {
      vec3 q = vec3(uv * 3.0, u_time);
      offset = (vec2(texture(u_noise, q).r, texture(u_noise, q + vec3(0.5, 0.25, 0.5)).r) * 2.0 - 1.0)
               * u_shimmer * fire;
    }
  }
  vec3 c = offset == vec2(0.0) ? texelFetch(scene, texel, 0).rgb : textureLod(scene, uv + offset, 0.0).rgb;
  return c * (1.0 - m.a) + m.rgb;
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
      c += u_left_matrix * media_color(u_left, u_left_depth, u_left_media, u_left_media_depth, texel, uv);
    if (u_use_right != 0)
      c += u_right_matrix * media_color(u_right, u_right_depth, u_right_media, u_right_media_depth, texel, uv);
  } else {
    if (u_use_left != 0) c += u_left_matrix * eye_color(u_left, u_left_layer, texel, uv);
    if (u_use_right != 0) c += u_right_matrix * eye_color(u_right, u_right_layer, texel, uv);
  }
  o_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
