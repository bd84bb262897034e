#pragma once
// GPU state of the particle pass: the kernel texture made from the footprint table, the
// instance buffer, and the programs (the real one and a trivial one used as a fill-rate
// baseline by `pyro bench render`).
#include "components/draw_list.h"
#include "systems/scene/scene_description.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "engine/math/camera_math.h"
#include "engine/math/footprint.h"
#include "systems/billboard_render/instance_buffer.h"

namespace pyro {

enum class BillboardShading { kernel, trivial };

class BillboardRenderer {
 public:
  explicit BillboardRenderer(const FootprintTable& table);

  // Uploads the sorted instances and blends them over `target` (depth tested, not written).
  void draw(const DrawList& list, const CameraFrame& frame, const gpu::RenderTarget& target,
            BillboardAlignment alignment = BillboardAlignment::viewplane,
            BillboardShading shading = BillboardShading::kernel);

  const FootprintTable& table() const { return table_; }

 private:
  FootprintTable table_;
  gpu::Program kernel_program_, trivial_program_;
  gpu::Texture kernel_texture_;
  InstanceBuffer instances_;
};

}  // namespace pyro
