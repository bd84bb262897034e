#pragma once
// GPU state of the anisotropic Gaussian pass (engine/particles/anisotropic_gaussian.h): the
// particles' records in a buffer of the GPU's memory (uploaded once for a static cloud), the
// back-to-front order for the frame's eye, and the program content/shaders/anisotropic_splat.
// {vert,frag}: one instance per particle over the exact screen rectangle of its ellipsoid
// (engine/math/projected_ellipsoid.h), each pixel shaded with the closed-form optical depth along
// its ray (engine/math/anisotropic_optical_depth.h), premultiplied, blended (ONE,
// ONE_MINUS_SRC_ALPHA) back to front, depth tested at the centre's depth and not written.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/particles/anisotropic_gaussian.h"

namespace pyro {

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
  // against its depth (not written).
  void draw(const CameraFrame& frame, const gpu::RenderTarget& target);

 private:
  gpu::Program program_;
  gpu::Buffer records_ = gpu::make_buffer();
  gpu::Buffer order_ = gpu::make_buffer();
  gpu::VertexArray empty_vao_ = gpu::make_vertex_array();
  std::vector<glm::vec3> centres_;
};

}  // namespace pyro
