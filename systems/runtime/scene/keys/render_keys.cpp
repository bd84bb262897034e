// "render": how the particles are drawn and composited.
#include "components/render_modes.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& render_fire_keys() {
  static const RenderDescription d{};
  static const ParameterTable table{
      "render.fire", "Fire under explosion shading: the black-body table and the emission.",
      {number_key("t_min", kPositive, "K; low end of the black-body table, below t_max.")
           .with_default(d.fire_t_min),
       number_key("t_max", kPositive, "K; high end of the table, above t_min.").with_default(d.fire_t_max),
       number_key("emission", kNonNegative, "Emitted radiance at t_max (linear).")
           .with_default(d.fire_emission),
       number_key("detail_range", kNonNegative, "K; the detail noise's temperature range.")
           .with_default(d.fire_detail_range)}};
  return table;
}

const ParameterTable& render_keys() {
  static const RenderDescription d{};
  static const ParameterTable table{
      "render", "How the particles are drawn and composited.",
      {enum_key<BillboardAlignment>("billboards", "Billboards facing the viewplane or the viewpoint.")
           .with_default(d.billboards),
       enum_key<ParticleShape>("particles", "Gaussian splats, spherical or planar billboards.")
           .with_default(d.particles),
       enum_key<ParticleShading>("shading", "\"explosion\" needs spherical or planar particles.")
           .with_default(d.shading),
       enum_key<SortDevice>("sort_device", "Where the splats' draw order is made.")
           .with_default(d.sort_device),
       number_key("layer_scale", Range{0.0, 1.0, true, false},
                  "Fraction of the view the particle layer is drawn at: 1, 0.5, 0.25 or 0.125.")
           .with_default(d.layer_scale),
       number_key("motion_blur", Range{0.0, 0.95}, "Each frame blends in this much of the previous one.")
           .with_default(d.motion_blur),
       object_key("fire", render_fire_keys(), "Fire under explosion shading.")}};
  return table;
}

}  // namespace pyro
