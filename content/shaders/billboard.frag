#version 450 core
// Opacity = density x footprint (Johnson & McAllister eqs. 5-7 with a black kernel texture):
// the kernel texture holds the scaled footprint table, the colour is the particle's own.
// Output is premultiplied; blending is (ONE, ONE_MINUS_SRC_ALPHA), back to front.
in vec2 v_texcoord;
flat in vec4 v_premultiplied;

layout(binding = 0) uniform sampler2D u_kernel;

layout(location = 0) out vec4 o_color;

void main() {
  o_color = v_premultiplied * textureLod(u_kernel, v_texcoord, 0.0).r;
}
