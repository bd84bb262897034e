#pragma once
// GPU state of the anisotropic Gaussian pass (engine/particles/anisotropic_gaussian.h): the
// particles' records in a buffer of the GPU's memory (uploaded once for a static cloud), the
// back-to-front order for the frame's eye, and the program content/shaders/anisotropic_splat.
// {vert,frag}: one instance per particle over the exact screen rectangle of its ellipsoid
// (engine/math/projected_ellipsoid.h), each pixel shaded with the closed-form optical depth along
// its ray (engine/math/anisotropic_optical_depth.h), premultiplied, blended (ONE,
// ONE_MINUS_SRC_ALPHA) back to front, depth tested at the centre's depth and not written.
// Lit (a scene with `shadows`), the particles' colours are albedos and each pixel is lit by the
// sun through the light phase's shadows (the LIT variant of the same program).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/math/scattering_octaves.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "systems/lighting/light_buffer.h"

namespace pyro {

// The light of a lit frame (docs/lighting.md), as the Gaussian splats get it (SplatLighting).
struct AnisotropicLighting {
  const LightBuffer* scene = nullptr;  // the scene's lights, which the renderer binds; required
  bool self_shadow = true;  // false: lit without shadows
  SunScattering scattering;
  // Per particle in the upload's order: the others' optical depth toward the sun at its centre
  // and its gradient (components/particle_light.h); shorter: the rest are unshadowed by others.
  std::vector<glm::vec4> others_depth;
};

// Indices of the particles with centres `centres`, farthest from `eye` first (distance to the
// centre; equal distances in ascending index).
std::vector<uint32_t> back_to_front_order(const std::vector<glm::vec3>& centres, const glm::vec3& eye);

class AnisotropicSplatRenderer {
 public:
  AnisotropicSplatRenderer();  // builds the program (throws GpuError with the driver's log)

  // Copies the particles' records into the GPU's memory; they are drawn until the next upload.
  // Rotations are normalised here (in double), so any non-zero quaternion will do.
  void upload(const std::vector<AnisotropicGaussian>& particles);
  std::size_t size() const { return centres_.size(); }

  // Orders the particles for frame.eye and blends them over `target`'s colour, depth tested
  // against its depth (not written); lit by `lighting` when given.
  void draw(const CameraFrame& frame, const gpu::RenderTarget& target,
            const AnisotropicLighting* lighting = nullptr);

 private:
  const gpu::Program& lit_program();
  void set_lighting(const AnisotropicLighting& lighting);

  gpu::Program program_;
  std::optional<gpu::Program> lit_program_;  // built on the first lit draw
  gpu::Buffer others_depth_ = gpu::make_buffer();
  gpu::Buffer records_ = gpu::make_buffer();
  gpu::Buffer order_ = gpu::make_buffer();
  gpu::VertexArray empty_vao_ = gpu::make_vertex_array();
  std::vector<glm::vec3> centres_;
};

}  // namespace pyro
