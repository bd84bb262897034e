// u = 1/z of the view depth z at a window depth d, affine in d: 1/n - d (f - n) / (n f) for the
// clip distances n, f, given as u_inverse_depth = (1/n, (f - n) / (n f))
// (engine/math/camera_math.h, inverse_depth_terms).
uniform vec2 u_inverse_depth;

float inverse_depth(float window_depth) {
  return u_inverse_depth.x - window_depth * u_inverse_depth.y;
}
