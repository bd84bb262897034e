#pragma once
// GPU side of flipbook fire (Rose 2007, chapter 4): each flipbook's frames in one sRGB 2D array
// texture (one layer per frame, mipmapped), and the billboards of a fire drawn as quads into a
// view's scene target, depth-tested against the opaque scene without writing depth, with the
// fire's blend: (1 - dst colour, 1) or linear alpha. A flipbook with motion vectors gets a second
// array (RG16F, frame UV per frame) and is drawn between its frames by the motion-vector blend
// (flipbook_motion_blend.h, content/shaders/flipbook.frag); without, each step shows its frame.
#include <vector>

#include "components/flipbook_fire.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "engine/math/camera_math.h"
#include "systems/flipbook_fire/flipbook_geometry.h"

namespace pyro {

class FlipbookRenderer {
 public:
  FlipbookRenderer();
  // Uploads a flipbook's frames; returns the index that FlipbookFire::texture refers to.
  int add_flipbook(const FlipbookFrames& frames);
  // Blends one fire's quads (back to front) into `target` as seen from `view`.
  void draw(const std::vector<FlipbookQuad>& quads, int texture, FlipbookBlend blend,
            const CameraFrame& view, const gpu::RenderTarget& target);

 private:
  gpu::Program program_;
  gpu::Buffer buffer_;
  gpu::VertexArray vao_;
  size_t capacity_ = 0;  // vertices
  struct Flipbook {
    gpu::Texture frames;
    gpu::Texture motion;  // empty when the flipbook has no motion vectors
    bool has_motion = false;
  };
  std::vector<Flipbook> flipbooks_;
  std::vector<float> vertices_;
};

}  // namespace pyro
