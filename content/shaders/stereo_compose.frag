#version 450 core
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
uniform mat3 u_left_matrix;
uniform mat3 u_right_matrix;
uniform int u_use_left;   // 0 when u_left_matrix is zero: skip the fetches
uniform int u_use_right;
uniform ivec2 u_origin;  // the viewport's lower-left corner in the output: views map 1:1
uniform vec2 u_view_size;

layout(location = 0) out vec4 o_color;

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
  if (u_use_left != 0) c += u_left_matrix * eye_color(u_left, u_left_layer, texel, uv);
  if (u_use_right != 0) c += u_right_matrix * eye_color(u_right, u_right_layer, texel, uv);
  o_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
