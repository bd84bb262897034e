// The sun's light scattered towards the eye per unit of sun colour (engine/math/scattering_octaves.h,
// sun_scattering: the sum over octaves i of b^i 4 pi p_HG(mu, c^i g) exp(-a^i tau)), from the
// uniforms u_octaves (1: single scattering) and u_scattering (g; the octaves' a, b, c), which the
// including shader declares. One isotropic octave is exp(-tau).
#include "henyey_greenstein.glsl"

float sun_scattering(float mu, float tau) {
  float sum = 0.0, a = 1.0, b = 1.0, g = u_scattering.x;
  for (int i = 0; i < u_octaves; ++i) {
    sum += b * 12.566370614359172 * henyey_greenstein(mu, g) * exp(-a * tau);
    a *= u_scattering.y;
    b *= u_scattering.z;
    g *= u_scattering.w;
  }
  return sum;
}

// The mean of sun_scattering(mu, tau.x) and sun_scattering(mu, tau.y), each octave's phase
// function evaluated once: the same sums in another order.
float sun_scattering_mean(float mu, vec2 tau) {
  float sum = 0.0, a = 1.0, b = 1.0, g = u_scattering.x;
  for (int i = 0; i < u_octaves; ++i) {
    vec2 t = exp(-a * tau);
    sum += b * 12.566370614359172 * henyey_greenstein(mu, g) * 0.5 * (t.x + t.y);
    a *= u_scattering.y;
    b *= u_scattering.z;
    g *= u_scattering.w;
  }
  return sum;
}
