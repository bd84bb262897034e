#pragma once
// GPU state of the opaque pass: one vertex/index buffer pair per mesh geometry drawn (by
// SharedMesh::id), released when no instance of the last draw used it.
#include <map>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "components/mesh_instance.h"
#include "components/render_settings.h"
#include "components/shadow_volume.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/mesh/mesh_data.h"
#include "systems/lighting/light_buffer.h"
#include "systems/lighting/mesh_shadow_texture.h"
#include "systems/lighting/opacity_map_texture.h"

namespace pyro {

class MeshRenderer {
 public:
  MeshRenderer();
  // Clears `target` to the background and draws every instance with depth. When the last draw
  // into this target had the same inputs (the instances, the view, the lights, the background and
  // the sRGB state: everything the image depends on), the target is left as it is if nothing was
  // drawn into it since (RenderTarget::binds(): particles in layers), else that image's colour
  // and depth are copied back (particles blended into it): the same bytes for a fraction of the
  // cost. The opaque scene of a still camera is drawn once. `shadows` (may be null or empty: no
  // shadows): the particle media's optical depth toward the key light, which dims its light;
  // `mesh_shadow` (may be null or empty): the meshes' own shadow from the key light.
  // `lights` (bound here): every sun, the ambient term and the explosion's fire lights.
  void draw(const std::vector<MeshInstance>& instances, const CameraFrame& frame,
            const RenderSettings& settings, const LightBuffer& lights,
            const gpu::RenderTarget& target, const ShadowVolume* shadows = nullptr,
            const MeshShadow* mesh_shadow = nullptr);
  // How many of the draws so far drew the meshes, and how many copied the last image back (the
  // others found it in place).
  int meshes_drawn() const { return meshes_drawn_; }
  int images_restored() const { return images_restored_; }

 private:
  struct GpuMesh {
    gpu::Buffer vertices, indices;
    gpu::VertexArray vao;
    GLsizei index_count = 0;
    bool closed = false;  // seen only from outside: back faces culled
  };
  // The buffers of `mesh`, uploaded on first use.
  const GpuMesh& mesh_for(const SharedMesh& mesh);
  // Releases the buffers of geometry that no instance of `instances` uses.
  void release_unused(const std::vector<MeshInstance>& instances);
  void draw_meshes(const std::vector<MeshInstance>& instances, const CameraFrame& frame,
                   const RenderSettings& settings, const LightBuffer& lights,
                   const gpu::RenderTarget& target, const ShadowVolume* shadows, const MeshShadow* mesh_shadow);
  // The GL state a draw leaves, set again after a copy.
  void leave_state(bool meshes, const RenderSettings& settings,
                   const gpu::RenderTarget& target) const;

  // The last draw into a target (by RenderTarget::serial()): its inputs and its image.
  struct Drawn {
    std::vector<float> inputs;
    glm::ivec3 shape{0};  // the target's width, height and colour format
    gpu::Texture color, depth;
    uint64_t binds = 0;  // the target's RenderTarget::binds() when this renderer left it
  };
  std::map<uint64_t, Drawn> drawn_;
  int meshes_drawn_ = 0, images_restored_ = 0;

  gpu::Program program_;         // linear output: a floating-point target, or GL encodes
  gpu::Program encode_program_;  // writes sRGB itself (srgb_encode.glsl), GL_FRAMEBUFFER_SRGB off
  // With n fire lights (mesh.frag's FIRE_LIGHTS n), by (encode, n), compiled on first use.
  std::map<std::pair<bool, int>, gpu::Program> fire_programs_;
  const gpu::Program& program_for(bool encode, int fire_lights);
  std::map<uint64_t, GpuMesh> meshes_;  // by SharedMesh::id
  OpacityMapTexture opacity_map_;
  MeshShadowTexture mesh_shadow_;
};

}  // namespace pyro
