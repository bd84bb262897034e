#pragma once
// GPU side of flipbook fire (Rose 2007, chapter 4): each flipbook's frames in one sRGB 2D array
// texture (one layer per frame, mipmapped), and the billboards of a fire drawn as quads into a
// view's scene target, depth-tested against the opaque scene without writing depth, with the
// fire's blend: (1 - dst colour, 1) or linear alpha. A flipbook with motion vectors gets a second
// array (RG16F, frame UV per frame) and is drawn between its frames by the motion-vector blend
// (flipbook_motion_blend.h, content/shaders/flipbook.frag); without, each step shows its frame.
// A six-way flipbook (smoke baked as lightmaps, flipbook_six_way_folder.h) gets its two lightmaps
// as linear RGBA8 arrays and is relit per fragment by Unity's six-way blend
// (systems/flipbook_fire/six_way_basis.h) under the light it is given, and drawn over what is
// behind it with premultiplied alpha whatever the fire's blend: it is a medium, not a glow.
#include <vector>

#include <glm/vec3.hpp>

#include "components/flipbook_draw_list.h"
#include "components/flipbook_fire.h"
#include "engine/gpu/gl_objects.h"
#include "engine/gpu/render_target.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "engine/math/camera_math.h"
#include "systems/flipbook_fire/flipbook_geometry.h"
#include "systems/lighting/light_buffer.h"

namespace pyro {

class FlipbookRenderer {
 public:
  FlipbookRenderer();
  // Uploads a flipbook's frames; returns the index that FlipbookFire::texture refers to.
  int add_flipbook(const FlipbookFrames& frames);
  // Blends one fire's quads (back to front) into `target` as seen from `view`. A six-way
  // flipbook is relit by `lights` (bound here) in the fire's frame `fire`; others ignore both.
  void draw(const std::vector<FlipbookQuad>& quads, int texture, FlipbookBlend blend, const FireFrame& fire,
            const LightBuffer& lights, const CameraFrame& view, const gpu::RenderTarget& target);

 private:
  gpu::Program program_;
  gpu::Buffer buffer_;
  gpu::VertexArray vao_;
  size_t capacity_ = 0;  // vertices
  struct Flipbook {
    gpu::Texture frames;
    gpu::Texture motion;  // empty when the flipbook has no motion vectors
    bool has_motion = false;
    gpu::Texture six_way_b;  // lightmap B of a six-way flipbook (`frames` then holds A)
    bool six_way = false;
  };
  std::vector<Flipbook> flipbooks_;
  std::vector<float> vertices_;
};

}  // namespace pyro
