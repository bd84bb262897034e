// Linear to sRGB (IEC 61966-2-1) for a pass that writes an sRGB target's bytes itself, with
// GL_FRAMEBUFFER_SRGB off: on llvmpipe GL's own conversion costs four times this. The toe, then
// a degree-5 polynomial in sqrt(v), largest error a twelfth of an 8-bit step; engine/math/color.h
// (linear_to_srgb_polynomial) is the same function on the CPU, with the fit and its test; its
// coefficients come from there as the define SRGB_POLYNOMIAL (srgb_polynomial_define()), which a
// program including this file must be given.
vec3 srgb_encode(vec3 linear) {
  const float c[6] = float[6](SRGB_POLYNOMIAL);
  vec3 v = clamp(linear, 0.0, 1.0);
  vec3 t = sqrt(v);
  vec3 p = ((((c[5] * t + c[4]) * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0];
  return mix(p, 12.92 * v, lessThanEqual(v, vec3(0.0031308)));
}
