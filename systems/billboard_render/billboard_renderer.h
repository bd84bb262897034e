#pragma once
// GPU state of the particle pass: the kernel texture made from the footprint table, the
// mapped buffer the particles are read from, and the programs (the real one and a trivial one used as a fill-rate
// baseline by `pyro bench render`).
#include <memory>
#include <optional>
#include <vector>

#include "components/draw_list.h"
#include "components/particle_light.h"
#include "components/shadow_settings.h"
#include "components/shadow_volume.h"
#include "systems/runtime/scene/scene_description.h"
#include "engine/gpu/buffer_range.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/math/footprint.h"
#include "engine/math/gaussian_line_integral.h"
#include "engine/math/scattering_octaves.h"
#include "engine/gpu/mapped_ring.h"
#include "systems/billboard_render/instance_buffer.h"  // UploadCost
#include "systems/gpu_sorting/gpu_depth_sort.h"
#include "systems/lighting/light_buffer.h"
#include "systems/lighting/opacity_map_texture.h"

namespace pyro {

enum class BillboardShading { kernel, trivial };

// Lit media (docs/lighting.md): beside each pool the light phase's light for its particles
// (components/particle_light.h; null: that pool's particles see the whole sun), and the scene's
// lights (the key light, the ambient term and the fire's point lights), which the renderer binds.
struct SplatLighting {
  std::vector<const ParticleLight*> lights;
  const LightBuffer* scene = nullptr;  // required
  bool self_shadow = true;  // false: lit without shadows
  SplatSunlight sunlight = SplatSunlight::fragments;  // where the sunlight is evaluated
  SunScattering scattering;  // the phase lobe and octaves (engine/math/scattering_octaves.h)
  // The light phase's opacity map (the map method): the fragments read the sunlight's depth from
  // it at each point they light (billboard.frag); null: from the particles' others' depth.
  const ShadowVolume* map = nullptr;
};

// CPU time of the particle pass since the last reset_cost(): packing the particles and copying
// the order into the GPU's memory and the wait for a free slot (engine/gpu/mapped_ring.h), and the time inside
// the draw calls (on llvmpipe the driver runs the vertex stage there, on the calling thread).
struct ParticlePassCost {
  UploadCost upload;
  double draw_call_ms = 0.0;
};

class BillboardRenderer {
 public:
  explicit BillboardRenderer(const FootprintTable& table);

  // Packs the particles and copies the list's order into the next slot of a persistently mapped
  // ring and blends the billboards over `target` (depth tested, not written), the vertex shader
  // reading each instance's record through the order (vertex pulling). An indexed
  // list (components/draw_list.h) points into `pools`; a gathered one is drawn as it is; one
  // left to the GPU is ordered there first (systems/gpu_sorting) and drawn indirectly. With
  // `lighting` the pools' colours are albedos, lit per fragment (billboard.frag, LIT); without,
  // the colours as given.
  void draw(const DrawList& list, const std::vector<const ParticlePool*>& pools,
            const CameraFrame& frame, const gpu::RenderTarget& target,
            BillboardAlignment alignment = BillboardAlignment::viewplane,
            BillboardShading shading = BillboardShading::kernel,
            const SplatLighting* lighting = nullptr);

  // The GPU's order of `list` (its gpu_request) timed to completion, after a warm-up run and
  // with the GPU idle before: what SortDevice::automatic weighs against the CPU's order. Draws
  // nothing.
  double time_gpu_order(const DrawList& list, const std::vector<const ParticlePool*>& pools);
  // The particles the last GPU order kept (reads back: waits for the GPU).
  uint32_t gpu_kept() const;

  const FootprintTable& table() const { return table_; }
  ParticlePassCost cost() const { return {{copy_ms_, ring_.wait_ms(), bytes_}, draw_call_ms_}; }
  void reset_cost() {
    ring_.reset_wait();
    copy_ms_ = draw_call_ms_ = 0.0;
    bytes_ = 0;
  }

 private:
  FootprintTable table_;
  // lit_program_: single isotropic scattering of the sun (LIT 1); scattering_program_: the
  // scattering lobe and octaves, and the fire lights (LIT 2). Their sunlight at the vertices
  // (SplatSunlight::vertices) is compiled on first use.
  gpu::Program kernel_program_, trivial_program_, lit_program_, scattering_program_;
  mutable std::optional<gpu::Program> lit_vertex_program_, scattering_vertex_program_;
  // With a thick particle among the last upload's (optical depth through its centre >= 1,
  // billboard.frag's THICK_PARTICLES), the fragments' programs that light thick particles where
  // the eye sees them, compiled on first use. Only a draw that holds one pays for them.
  mutable std::optional<gpu::Program> lit_thick_program_, scattering_thick_program_;
  bool thick_ = false;
  gpu::Texture kernel_texture_;
  // The lit program's self-shadow: gaussian_tail_polynomial's coefficients.
  std::array<double, kTailPolynomialTerms> tail_polynomial_ = gaussian_tail_polynomial();
  // Packs the particles (the pools of an indexed list, or a gathered list's arrays) as two vec4s
  // each and the list's order straight into the next slot of ring_, and binds them (SSBO
  // bindings 0 and 1).
  // A list the GPU orders gets the particles' ids in place of the order.
  // With `lighting`, also each particle's others' depth (binding 2).
  void upload(const DrawList& list, const std::vector<const ParticlePool*>& pools,
              const SplatLighting* lighting = nullptr);
  // The lit program's uniforms.
  const gpu::Program& lit_program(const SplatLighting& lighting) const;
  void set_lighting_uniforms(const SplatLighting& lighting);
  // The last upload's particles ordered by gpu_sort_ (made on first use).
  void order_on_gpu(const DrawList& list, const std::vector<const ParticlePool*>& pools);

  // Where the last upload put the records, and the order (or the ids).
  gpu::BufferRange uploaded_records_, uploaded_order_, uploaded_shadow_;
  std::unique_ptr<GpuDepthSort> gpu_sort_;

  gpu::MappedRing ring_;
  OpacityMapTexture sunlight_map_{OpacityMapHolds::transmittance};
  gpu::VertexArray empty_vao_ = gpu::make_vertex_array();
  double copy_ms_ = 0.0, draw_call_ms_ = 0.0;
  std::size_t bytes_ = 0;
};

}  // namespace pyro
