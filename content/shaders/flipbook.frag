#version 450 core
// One flame frame, colour scaled by the billboard's intensity and brought within 1, as the
// thesis' fixed-point framebuffer needs (section 4.3): rolled off keeping its hue
// (highlight_rolloff.glsl), not clipped per channel, which would turn a brightened orange
// yellow. The blend itself is fixed-function: (1 - dst, 1) or (src alpha, 1 - src alpha),
// chosen per fire.
// With motion vectors (u_has_motion), the billboard shows the flame between frame a (layer) and
// frame b (next layer), a fraction t of the way: the standard motion-vector flipbook blend
// (systems/flipbook_fire/flipbook_motion_blend.h, as Unity's Flipbook Motion Blend and Unreal's
// FlipBook_MotionVectors do it) samples a at uv - t m_a(uv) and b at uv + (1 - t) m_b(uv) and
// mixes them by t; m is a frame's motion over one frame in UV (v down, as these UVs), times the
// frames b lies ahead of a. Without motion vectors, t is 0 and the frame is shown as it is.
in vec3 v_uv_layer;
in float v_intensity;
in vec3 v_next_blend_scale;  // next layer, t, motion scale

layout(binding = 0) uniform sampler2DArray u_frames;  // sRGB texels, read as linear
layout(binding = 1) uniform sampler2DArray u_motion;  // RG: motion over one frame, frame UV
uniform bool u_has_motion;

#include "highlight_rolloff.glsl"

layout(location = 0) out vec4 o_color;

void main() {
  vec4 t;
  if (u_has_motion) {
    const vec2 uv = v_uv_layer.xy;
    const float a = v_uv_layer.z, b = v_next_blend_scale.x, f = v_next_blend_scale.y;
    const vec2 m_a = texture(u_motion, vec3(uv, a)).rg * v_next_blend_scale.z;
    const vec2 m_b = texture(u_motion, vec3(uv, b)).rg * v_next_blend_scale.z;
    t = mix(texture(u_frames, vec3(uv - f * m_a, a)), texture(u_frames, vec3(uv + (1.0 - f) * m_b, b)), f);
  } else {
    t = texture(u_frames, v_uv_layer);
  }
  o_color = vec4(roll_off_highlights(t.rgb * v_intensity), t.a);
}
