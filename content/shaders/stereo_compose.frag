#version 450 core
// Composes the output image from the left and right views as out = L * left + R * right,
// clamped, on linear values (engine/math/anaglyph.h gives the matrices: identity/zero for a
// single view, Dubois or colour/half-colour for anaglyphs). The target is sRGB: GL encodes.
in vec2 v_uv;

layout(binding = 0) uniform sampler2D u_left;
layout(binding = 1) uniform sampler2D u_right;
uniform mat3 u_left_matrix;
uniform mat3 u_right_matrix;

layout(location = 0) out vec4 o_color;

void main() {
  vec3 c = u_left_matrix * textureLod(u_left, v_uv, 0.0).rgb +
           u_right_matrix * textureLod(u_right, v_uv, 0.0).rgb;
  o_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
