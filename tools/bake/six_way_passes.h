#pragma once
// The lighting passes of a six-way bake, for one simulation state: the scene's own lights are
// replaced by a white sun along each face's axis of the camera's frame (ambient 0), then by
// ambient light 1 alone (no sun), whose render of a white medium over black is its opacity
// (six_way_frame.h). The light phase runs again for every pass (shadows included); the
// simulation does not.
#include <array>
#include <functional>
#include <glm/vec3.hpp>

#include "engine/math/camera_math.h"
#include "systems/runtime/reference/rgb_image.h"
#include "systems/flipbook_fire/six_way_basis.h"

namespace pyro {

// What a pass sets: the sun's travel direction (world space; ignored when `sun` is 0) and
// colour, and the ambient colour.
struct SixWayPassLight {
  glm::vec3 travel{0.0f, -1.0f, 0.0f};
  glm::vec3 sun{1.0f};
  glm::vec3 ambient{0.0f};
};

// The world-space direction a face's light travels for a camera (the opposite of
// six_way_towards_light, turned into the world by the camera's right, up and -forward).
glm::vec3 six_way_light_travel(const CameraFrame& camera, const glm::vec3& towards_light_camera);

// The pass lighting face f, and the opacity pass.
SixWayPassLight six_way_face_pass(const CameraFrame& camera, SixWayFace f);
SixWayPassLight six_way_opacity_pass();

// The seven renders (six faces, then opacity) of one state, each drawn by `render`.
struct SixWayRenders {
  std::array<RgbImage, kSixWayFaces> faces;
  RgbImage opacity;
};
SixWayRenders render_six_way_passes(const CameraFrame& camera,
                                    const std::function<RgbImage(const SixWayPassLight&)>& render);

}  // namespace pyro
