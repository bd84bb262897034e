#pragma once
// GPU state of the particle pass: the kernel texture made from the footprint table, the
// mapped buffer the particles are read from, and the programs (the real one and a trivial one used as a fill-rate
// baseline by `pyro bench render`).
#include "components/draw_list.h"
#include "systems/scene/scene_description.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/math/footprint.h"
#include "engine/gpu/mapped_ring.h"
#include "systems/billboard_render/instance_buffer.h"  // UploadCost

namespace pyro {

enum class BillboardShading { kernel, trivial };

// CPU time of the particle pass since the last reset_cost(): the records' and order's copy into
// the GPU's memory and the wait for a free slot (engine/gpu/mapped_ring.h), and the time inside
// the draw calls (on llvmpipe the driver runs the vertex stage there, on the calling thread).
struct ParticlePassCost {
  UploadCost upload;
  double draw_call_ms = 0.0;
};

class BillboardRenderer {
 public:
  explicit BillboardRenderer(const FootprintTable& table);

  // Copies the particle records and the list's order into the next slot of a persistently
  // mapped ring and blends the billboards over `target` (depth tested, not written), the vertex
  // shader reading each instance's record through the order (vertex pulling). An indexed list
  // (components/draw_list.h) points into `records`; a gathered one is drawn as it is.
  void draw(const DrawList& list, const std::vector<glm::vec4>& records, const CameraFrame& frame,
            const gpu::RenderTarget& target,
            BillboardAlignment alignment = BillboardAlignment::viewplane,
            BillboardShading shading = BillboardShading::kernel);

  const FootprintTable& table() const { return table_; }
  ParticlePassCost cost() const { return {{copy_ms_, ring_.wait_ms(), bytes_}, draw_call_ms_}; }
  void reset_cost() {
    ring_.reset_wait();
    copy_ms_ = draw_call_ms_ = 0.0;
    bytes_ = 0;
  }

 private:
  FootprintTable table_;
  gpu::Program kernel_program_, trivial_program_;
  gpu::Texture kernel_texture_;
  // Binds the records and the order (SSBO bindings 0 and 1) from the next slot of ring_.
  void upload(const std::vector<glm::vec4>& records, const std::vector<uint32_t>& order);

  gpu::MappedRing ring_;
  gpu::VertexArray empty_vao_ = gpu::make_vertex_array();
  std::vector<glm::vec4> own_records_;  // a gathered list's records
  std::vector<uint32_t> own_order_;     // and its order, 0 .. n-1
  double copy_ms_ = 0.0, draw_call_ms_ = 0.0;
  std::size_t bytes_ = 0;
};

}  // namespace pyro
