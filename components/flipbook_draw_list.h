#pragma once
// Resource: this frame's flipbook fire billboards in world space, one set for every eye (Rose
// 2007, section 4.6: the group faces the mid-eye point, so both eyes see the same group), written
// by the flipbook_orient system and drawn by flipbook_render. Fires farthest from the mid-eye
// first; each fire's quads back to front.
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "components/flipbook_fire.h"

namespace pyro {

// The fire's frame: origin at the base centre; `up` the base normal; `toward` the horizontal
// (in the base plane) direction to the viewer; right = up x toward. All unit and orthogonal.
struct FireFrame {
  glm::vec3 origin{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  glm::vec3 toward{0.0f, 0.0f, 1.0f};
  glm::vec3 right{1.0f, 0.0f, 0.0f};
};

struct FlipbookQuad {
  // bottom-left, bottom-right, top-left, top-right (as seen from the viewer)
  std::array<glm::vec3, 4> corners{};
  int frame = 0;            // texture layer
  // Between frames (a flipbook with motion vectors): the next frame's layer, the fraction of the
  // way to it, and the frames it lies ahead (the billboard's increment, which scales the motion).
  int next_frame = 0;
  float blend = 0.0f;
  float motion_scale = 1.0f;
  float intensity = 1.0f;   // colour scale
  float depth = 0.0f;       // along `toward` in the fire's frame: larger is nearer the viewer
};

struct FlipbookDrawList {
  struct Fire {
    FireFrame frame;                  // the group's orientation this frame
    std::vector<FlipbookQuad> quads;  // back to front
    int texture = -1;
    FlipbookBlend blend = FlipbookBlend::one_minus_destination;
    float distance = 0.0f;            // base centre to the mid-eye
  };
  glm::vec3 viewer{0.0f};  // the mid-eye point the groups face
  std::vector<Fire> fires;
};

}  // namespace pyro
