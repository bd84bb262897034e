#pragma once
// GPU state of explosion shading (Umenhoffer et al. 2006, sections 3 and 4): spherical (or, for
// comparison, planar) billboards of dust, smoke and fire, each medium into its own layer, shaded
// by eq. 1: the Cornette-Shanks phase function in closed form (in the shader), and tables made in
// engine/math: the black-body table and the detail-noise volume (its slice at each frame's time).
#include <array>
#include <memory>

#include "components/draw_list.h"
#include "components/explosion_shading.h"
#include "components/fire_lights.h"
#include "components/render_settings.h"
#include "systems/lighting/light_buffer.h"
#include "systems/lighting/mesh_shadow_texture.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/math/detail_noise.h"
#include "systems/billboard_render/instance_buffer.h"
#include "systems/billboard_render/sphere_billboard_programs.h"

namespace pyro {

// Splits a back-to-front draw list by medium (components/particle_medium.h), keeping the order.
void split_by_medium(const DrawList& list, std::array<DrawList, 3>& out);

// How dust and smoke see the sun (sphere_billboard.frag, LIT): shadowed by themselves alone
// (unlit: no light phase), by the light phase's others' depth (DrawList::light) too, or by every
// particle exactly, per fragment.
enum class MediaLighting { unlit, light_phase, exact };

class ExplosionRenderer {
 public:
  explicit ExplosionRenderer(const ExplosionShading& shading);
  // Clears the three layers, then blends each medium's particles (back to front) into its layer:
  // cell m of `atlas` (components/gpu_frame.h), `cell_width` columns wide.
  // `scene` holds the opaque scene's colour and depth (the spherical shader clips against its
  // full-resolution depth; planar billboards are depth tested against a point-sampled copy).
  // `media_lighting` light_phase needs list.light. Lit, dust and smoke are lit by `lights`' key
  // light and ambient term and scatter the fire's light: the block's clustered lights, or with
  // exact every emitter of `fire` (may be null: none), and with exact the meshes' shadow
  // `mesh_shadow` per fragment (may be null; the light phase puts it in list.light otherwise).
  void draw(const DrawList& list, const CameraFrame& frame, const RenderSettings& settings,
            const LightBuffer& lights, double time, const gpu::RenderTarget& atlas,
            int cell_width, const gpu::RenderTarget& scene,
            MediaLighting media_lighting = MediaLighting::unlit, const FireLights* fire = nullptr,
            const MeshShadow* mesh_shadow = nullptr);
  const ExplosionShading& shading() const { return shading_; }

 private:
  ExplosionShading shading_;
  SphereBillboardPrograms programs_;
  std::array<InstanceBuffer, 3> instances_;
  std::array<DrawList, 3> split_;
  void upload_detail_slice(double time);
  // MediaLighting::exact: every particle of `list` in view space, into casters_ (binding 5), and
  // every fire emitter, into emitters_ (binding 6).
  void upload_casters(const DrawList& list, const CameraFrame& frame);
  void upload_fire_emitters(const FireLights* fire, const CameraFrame& frame);
  gpu::Buffer casters_, emitters_;
  GLsizeiptr casters_bytes_ = 0, emitters_bytes_ = 0;
  gpu::Texture blackbody_, detail_;
  MeshShadowTexture mesh_shadow_;
  DetailNoise detail_volume_;
  float detail_time_ = -1.0f;
};

}  // namespace pyro
