#pragma once
// GPU state of the opaque pass: one vertex/index buffer pair per procedural mesh kind.
#include <map>

#include "components/mesh_instance.h"
#include "components/render_settings.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/mesh/mesh_data.h"

namespace pyro {

class MeshRenderer {
 public:
  MeshRenderer();
  // Clears `target` to the background and draws every instance with depth.
  void draw(const std::vector<MeshInstance>& instances, const CameraFrame& frame,
            const RenderSettings& settings, const gpu::RenderTarget& target);

 private:
  struct GpuMesh {
    gpu::Buffer vertices, indices;
    gpu::VertexArray vao;
    GLsizei index_count = 0;
    bool closed = false;  // seen only from outside: back faces culled
  };
  const GpuMesh& mesh_for(MeshKind kind);

  gpu::Program program_;         // linear output: a floating-point target, or GL encodes
  gpu::Program encode_program_;  // writes sRGB itself (srgb_encode.glsl), GL_FRAMEBUFFER_SRGB off
  std::map<MeshKind, GpuMesh> meshes_;
};

}  // namespace pyro
