#include "tools/bake/six_way_passes.h"

namespace pyro {

glm::vec3 six_way_light_travel(const CameraFrame& camera, const glm::vec3& towards_light_camera) {
  const glm::vec3 towards = camera.right * towards_light_camera.x +
                            camera.up * towards_light_camera.y -
                            camera.forward * towards_light_camera.z;
  return -towards;
}

SixWayPassLight six_way_face_pass(const CameraFrame& camera, SixWayFace f) {
  SixWayPassLight pass;
  pass.travel = six_way_light_travel(camera, six_way_towards_light(f));
  return pass;
}

SixWayPassLight six_way_opacity_pass() {
  SixWayPassLight pass;
  pass.sun = glm::vec3(0.0f);
  pass.ambient = glm::vec3(1.0f);
  return pass;
}

SixWayRenders render_six_way_passes(const CameraFrame& camera,
                                    const std::function<RgbImage(const SixWayPassLight&)>& render) {
  SixWayRenders renders;
  for (int i = 0; i < kSixWayFaces; ++i)
    renders.faces[i] = render(six_way_face_pass(camera, static_cast<SixWayFace>(i)));
  renders.opacity = render(six_way_opacity_pass());
  return renders;
}

}  // namespace pyro
