#version 450 core
// Opacity of a spherical particle along this pixel's ray (Umenhoffer et al. 2006, eq. 2 and
// section 2.2): alpha = 1 - exp(-tau (1 - d/r) ds), where d is the ray's distance from the
// centre and ds the length of the ray inside the sphere, clipped by the near plane and by the
// opaque scene's depth. Unlike the paper, which takes rays parallel to z inside a particle,
// ds comes from the exact ray-sphere intersection of the perspective ray.
// Output premultiplied; blending (ONE, ONE_MINUS_SRC_ALPHA), back to front.
flat in vec3 v_center;
flat in float v_radius;
flat in vec4 v_color_tau;

layout(binding = 1) uniform sampler2D u_scene_depth;  // window depth of the opaque scene
uniform vec2 u_depth_scale;     // scene-depth texels per target pixel
uniform vec2 u_viewport;        // target size in pixels
uniform vec4 u_projection_terms;  // P[0][0], P[1][1], P[2][0], P[2][1] (off-axis terms)
uniform float u_near;
uniform float u_far;
uniform int u_planar;

layout(location = 0) out vec4 o_color;

float view_depth(float window_depth) {
  float z_ndc = window_depth * 2.0 - 1.0;
  return 2.0 * u_near * u_far / (u_far + u_near - z_ndc * (u_far - u_near));
}

void main() {
  vec2 ndc = gl_FragCoord.xy / u_viewport * 2.0 - 1.0;
  // The ray through this pixel, scaled so that its parameter is the view depth.
  vec3 dir = vec3((ndc.x + u_projection_terms.z) / u_projection_terms.x,
                  (ndc.y + u_projection_terms.w) / u_projection_terms.y, -1.0);
  vec3 p = v_center;
  float r = v_radius;
  float a = dot(dir, dir);
  float b = dot(dir, p);
  float c = dot(p, p) - r * r;
  float distance2 = max(dot(p, p) - b * b / a, 0.0);  // squared distance of the ray from p
  if (distance2 >= r * r) discard;
  float d = sqrt(distance2);
  float ds;
  if (u_planar != 0) {
    // The planar billboard: the full chord, wherever the plane is.
    ds = 2.0 * sqrt(r * r - distance2);
  } else {
    float h = sqrt(max(b * b - a * c, 0.0));
    float enter = (b - h) / a, leave = (b + h) / a;  // view depths
    float scene = view_depth(texelFetch(u_scene_depth, ivec2(gl_FragCoord.xy * u_depth_scale), 0).r);
    float from = max(enter, u_near), to = min(leave, scene);
    ds = max(to - from, 0.0) * sqrt(a);  // view depth to path length
  }
  float alpha = 1.0 - exp(-v_color_tau.a * (1.0 - d / r) * ds);
  o_color = vec4(v_color_tau.rgb * alpha, alpha);
}
