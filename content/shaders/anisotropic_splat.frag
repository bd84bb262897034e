#version 450 core
// The optical depth of one anisotropic Gaussian particle along the pixel's ray from the eye,
// in closed form: engine/math/anisotropic_optical_depth.h (anisotropic_ray_segment and
// AnisotropicRaySegment::depth over t in [0, infinity)), evaluated here step for step in float.
// The ray is the eye towards the pixel's point on the far plane (the inverse view-projection,
// applied at the quad's corners and interpolated: anisotropic_splat.vert), so a camera inside a
// particle sees the particle's density ahead of it, not a flat card.
// erf is Abramowitz & Stegun 7.1.26 (|error| <= 1.5e-7), its coefficients the uniform
// u_erf = kErfAs7126 {p, a1, a2, a3, a4, a5} from the same header.
// Output is premultiplied (colour alpha, alpha), alpha = 1 - exp(-tau); blending is
// (ONE, ONE_MINUS_SRC_ALPHA), back to front.
noperspective in vec3 v_ray;           // d: the ray's direction, unnormalised
noperspective in vec3 v_ray_whitened;  // M d, M = S^-1 R^T
flat in vec3 v_eye_whitened;           // u0 = M (eye - c)
flat in vec4 v_color_extinction;

uniform float u_erf[6];

layout(location = 0) out vec4 o_color;

const float kExtent = 3.0;  // engine/particles/anisotropic_gaussian.h: kAnisotropicExtent
const float kPi = 3.14159265358979;

float erf_as_7_1_26(float x) {
  float ax = abs(x);
  float t = 1.0 / (1.0 + u_erf[0] * ax);
  float poly = t * (u_erf[1] + t * (u_erf[2] + t * (u_erf[3] + t * (u_erf[4] + t * u_erf[5]))));
  float y = 1.0 - poly * exp(-ax * ax);
  return x < 0.0 ? -y : y;
}

void main() {
  // anisotropic_ray_segment, with w = d / |d| and so v = M w = (M d) / |d|:
  vec3 v = v_ray_whitened / length(v_ray);
  float a = dot(v, v);
  float t_closest = -dot(v_eye_whitened, v) / a;
  vec3 closest = v_eye_whitened + t_closest * v;
  float m2_min = dot(closest, closest);
  float e2 = kExtent * kExtent;
  if (!(m2_min < e2)) discard;
  float h = sqrt((e2 - m2_min) / a);
  float t_enter = t_closest - h, t_exit = t_closest + h;
  float rate = sqrt(0.5 * a);
  float peak = v_color_extinction.a * exp(-0.5 * m2_min) * sqrt(kPi / (2.0 * a));
  // AnisotropicRaySegment::depth(0, infinity):
  float lo = max(0.0, t_enter), hi = t_exit;
  if (!(hi > lo)) discard;
  float tau = peak * (erf_as_7_1_26(rate * (hi - t_closest)) - erf_as_7_1_26(rate * (lo - t_closest)));
  float alpha = 1.0 - exp(-tau);
  o_color = vec4(v_color_extinction.rgb * alpha, alpha);
}
