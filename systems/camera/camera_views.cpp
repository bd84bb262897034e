#include "systems/camera/camera_views.h"

namespace pyro {

CameraFrame mono_frame(const Camera& c, const RenderSettings& s) {
  return make_camera_frame(c.position, c.target, c.up, c.fov_y_deg, c.near, c.far, s.width, s.height);
}

std::vector<CameraFrame> rendered_views(const Camera& camera, const StereoCamera* stereo,
                                        const RenderSettings& settings) {
  const CameraFrame mono = mono_frame(camera, settings);
  if (!is_stereo(settings.stereo_mode)) return {mono};
  const StereoParameters p = stereo ? stereo->parameters : StereoParameters{};
  return {make_eye_frame(mono, p, Eye::left), make_eye_frame(mono, p, Eye::right)};
}

}  // namespace pyro
