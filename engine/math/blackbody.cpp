#include "engine/math/blackbody.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace pyro {

double planck_radiance(double wavelength_m, double temperature_k) {
  const double l = wavelength_m;
  const double l5 = l * l * l * l * l;
  // expm1 keeps the long-wavelength / high-temperature limit (Rayleigh–Jeans) accurate.
  return 2.0 * planck_h * light_c * light_c / (l5 * std::expm1(planck_c2 / (l * temperature_k)));
}

namespace {

// Trapezoid rule of S(λ) · (x̄, ȳ, z̄) over the table; S takes the wavelength in nm.
template <class Spectrum>
glm::dvec3 integrate_cmf(const ColorMatchingFunctions& cmf, double dlambda, Spectrum s) {
  glm::dvec3 sum(0.0);
  const std::size_t n = cmf.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double w = (i == 0 || i + 1 == n) ? 0.5 : 1.0;
    const double v = w * s(cmf.wavelength_nm(i));
    sum += v * glm::dvec3(cmf.x[i], cmf.y[i], cmf.z[i]);
  }
  return sum * dlambda;
}

}  // namespace

glm::dvec3 blackbody_xyz(double temperature_k, const ColorMatchingFunctions& cmf) {
  if (!(temperature_k > 0.0))
    throw std::invalid_argument("blackbody_xyz: temperature must be > 0 K, got " +
                                std::to_string(temperature_k));
  return integrate_cmf(cmf, cmf.step_nm * 1e-9,
                       [&](double nm) { return planck_radiance(nm * 1e-9, temperature_k); });
}

glm::dvec3 equal_energy_xyz(const ColorMatchingFunctions& cmf) {
  return integrate_cmf(cmf, cmf.step_nm, [](double) { return 1.0; });
}

glm::dvec2 xyz_chromaticity(const glm::dvec3& xyz) {
  const double s = xyz.x + xyz.y + xyz.z;
  return {xyz.x / s, xyz.y / s};
}

glm::dvec3 xyz_to_linear_srgb(const glm::dvec3& v) {
  // IEC 61966-2-1:1999, eq. (5.2.3)'s inverse as the standard prints it (four decimals).
  return {3.2406 * v.x - 1.5372 * v.y - 0.4986 * v.z,
          -0.9689 * v.x + 1.8758 * v.y + 0.0415 * v.z,
          0.0557 * v.x - 0.2040 * v.y + 1.0570 * v.z};
}

glm::dvec2 linear_srgb_chromaticity(const glm::dvec3& rgb) {
  glm::dmat3 to_rgb;
  for (int c = 0; c < 3; ++c) {
    glm::dvec3 e(0.0);
    e[c] = 1.0;
    to_rgb[c] = xyz_to_linear_srgb(e);
  }
  return xyz_chromaticity(glm::inverse(to_rgb) * rgb);
}

BlackbodyColor blackbody_color(double temperature_k, const ColorMatchingFunctions& cmf) {
  BlackbodyColor c;
  c.temperature_k = temperature_k;
  const glm::dvec3 xyz = blackbody_xyz(temperature_k, cmf);
  c.luminance = luminous_efficacy_km * xyz.y;
  c.xyz = xyz / xyz.y;
  c.xy = xyz_chromaticity(xyz);
  glm::dvec3 rgb = xyz_to_linear_srgb(c.xyz);
  c.in_gamut = rgb.x >= 0.0 && rgb.y >= 0.0 && rgb.z >= 0.0;
  rgb = {std::max(rgb.x, 0.0), std::max(rgb.y, 0.0), std::max(rgb.z, 0.0)};
  c.rgb = rgb / std::max({rgb.x, rgb.y, rgb.z});
  return c;
}

BlackbodyTable make_blackbody_table(double t_min, double t_max, int size,
                                    const ColorMatchingFunctions& cmf) {
  if (size < 2 || !(t_min > 0.0) || !(t_max > t_min))
    throw std::invalid_argument("make_blackbody_table: need size >= 2 and 0 < t_min < t_max");
  BlackbodyTable t;
  t.t_min = t_min;
  t.t_max = t_max;
  t.size = size;
  t.rgb.resize(static_cast<std::size_t>(size) * 3);
  t.luminance.resize(static_cast<std::size_t>(size));
  for (int i = 0; i < size; ++i) {
    const double temp = t_min + (t_max - t_min) * i / (size - 1);
    const BlackbodyColor c = blackbody_color(temp, cmf);
    for (int k = 0; k < 3; ++k) t.rgb[static_cast<std::size_t>(i) * 3 + k] = static_cast<float>(c.rgb[k]);
    t.luminance[static_cast<std::size_t>(i)] = static_cast<float>(c.luminance);
  }
  return t;
}

BlackbodyTable blackbody_emission_table(double t_min, double t_max, float emission, int size) {
  BlackbodyTable t = make_blackbody_table(t_min, t_max, size);
  const float top = t.luminance.back() > 0.0f ? t.luminance.back() : 1.0f;
  for (int i = 0; i < size; ++i)
    for (int c = 0; c < 3; ++c) {
      float& v = t.rgb[static_cast<std::size_t>(i) * 3 + c];
      v = v * t.luminance[static_cast<std::size_t>(i)] / top * emission;
    }
  return t;
}

glm::vec3 sample_blackbody_rgb(const BlackbodyTable& t, double temperature_k) {
  const double u = std::clamp((temperature_k - t.t_min) / (t.t_max - t.t_min), 0.0, 1.0) * (t.size - 1);
  const int i = std::min(static_cast<int>(u), t.size - 2);
  const float f = static_cast<float>(u - i);
  const float* a = &t.rgb[static_cast<std::size_t>(i) * 3];
  const float* b = a + 3;
  return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

}  // namespace pyro
