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
// A six-way flipbook (u_six_way: smoke baked under six lights, Unity VFX Graph's packing, A =
// right/top/back + alpha, B = left/bottom/front + emissive; tools/bake/
// six_way_basis.h) is relit here by Unity's blend (URP SixWayLighting.hlsl, SixWayLightBlend):
// with w the unit vector towards a sun in the fire's frame (x right, y up, z toward the viewer),
// lighting = sum over the axes of w_axis^2 times the face on w_axis's side. The smoke's colour is
// (sum over the suns of radiance lighting + ambient + emissive) alpha, premultiplied: it is
// blended over. The suns and the ambient term are the scene's (lights.glsl).
in vec3 v_uv_layer;
in float v_intensity;
in vec3 v_next_blend_scale;  // next layer, t, motion scale

layout(binding = 0) uniform sampler2DArray u_frames;  // sRGB texels, read as linear
layout(binding = 1) uniform sampler2DArray u_motion;  // RG: motion over one frame, frame UV
uniform bool u_has_motion;
layout(binding = 2) uniform sampler2DArray u_six_way_b;  // left, bottom, front, emissive: linear
uniform bool u_six_way;
uniform vec3 u_fire_right;   // the fire's frame in world space (components/flipbook_draw_list.h)
uniform vec3 u_fire_up;
uniform vec3 u_fire_toward;
#include "lights.glsl"

#include "highlight_rolloff.glsl"

layout(location = 0) out vec4 o_color;

// Lightmap A (right, top, back, alpha) and B (left, bottom, front, emissive) relit.
vec4 six_way_lit(vec4 a, vec4 b) {
  const vec3 positive = vec3(a.r, a.g, b.b);  // right (+x), top (+y), front (+z)
  const vec3 negative = vec3(b.r, b.g, a.b);  // left (-x), bottom (-y), back (-z)
  vec3 direct = vec3(0.0);
  for (int i = 0; i < sun_count(); ++i) {
    const vec3 t = toward_sun(i);
    const vec3 w = vec3(dot(t, u_fire_right), dot(t, u_fire_up), dot(t, u_fire_toward));
    direct += sun_radiance(i) * dot(w * w, mix(negative, positive, greaterThanEqual(w, vec3(0.0))));
  }
  const vec3 color = (direct + ambient_light() + vec3(b.a)) * v_intensity;
  return vec4(color * a.a, a.a);
}

void main() {
  if (u_six_way) {
    o_color = six_way_lit(texture(u_frames, v_uv_layer), texture(u_six_way_b, v_uv_layer));
    return;
  }
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
