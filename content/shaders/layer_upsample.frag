#version 450 core
// Composites a reduced-resolution particle layer (premultiplied) over the full-resolution
// scene: bilinear upsampling, blended with (ONE, ONE_MINUS_SRC_ALPHA).
in vec2 v_uv;

layout(binding = 0) uniform sampler2D u_layer;

layout(location = 0) out vec4 o_color;

void main() {
  o_color = textureLod(u_layer, v_uv, 0.0);
}
