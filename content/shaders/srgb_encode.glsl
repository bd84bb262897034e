// Linear to sRGB (IEC 61966-2-1) for a pass that writes an sRGB target's bytes itself, with
// GL_FRAMEBUFFER_SRGB off: on llvmpipe GL's own conversion costs four times this. The toe, then
// a degree-5 polynomial in sqrt(v), largest error a twelfth of an 8-bit step; engine/math/color.h
// (linear_to_srgb_polynomial) is the same function on the CPU, with the fit and its test.
vec3 srgb_encode(vec3 linear) {
  vec3 v = clamp(linear, 0.0, 1.0);
  vec3 t = sqrt(v);
  vec3 p = ((((0.51493223 * t - 1.61693199) * t + 2.02471918) * t - 1.39971863) * t +
            1.51741072) * t - 0.0400807126;
  return mix(p, 12.92 * v, lessThanEqual(v, vec3(0.0031308)));
}
