#include "systems/runtime/scene_runtime/render_identity.h"

#include <limits>

#include "engine/core/cache_folder.h"
#include "engine/io/content_digest.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"
#include "systems/runtime/scene_runtime/run_identity.h"

namespace pyro {

nlohmann::json pixel_settings(const SceneDescription& scene, const RuntimeOptions& o) {
  RuntimeOptions requested = o;
  requested.quality.reset();
  const RenderSettings rs =
      resolve_scene(scene, requested, std::numeric_limits<int>::max()).settings;
  nlohmann::json s = {{"width", rs.width},
                      {"height", rs.height},
                      {"stereo", name_of(rs.stereo_mode)},
                      {"billboards", name_of(rs.alignment)},
                      {"particles", name_of(rs.particles)},
                      {"layer_scale", rs.layer_scale},
                      {"frame_scale", o.frame_scale}};
  if (rs.transparent) s["background"] = "none";  // absent when opaque: earlier runs' identities stay
  if (o.shading) s["shading"] = name_of(*o.shading);
  if (o.shadows_off)
    s["shadows"] = "off";
  else if (o.shadow_method)
    s["shadows"] = name_of(*o.shadow_method);
  if (o.interocular) s["interocular"] = *o.interocular;
  if (o.zero_parallax_distance) s["zero_parallax"] = *o.zero_parallax_distance;
  if (o.swap_eyes) s["swap_eyes"] = *o.swap_eyes;
  return s;
}

nlohmann::json render_identity_json(const SceneDescription& scene, const RuntimeOptions& options,
                                    const std::string& scene_file, bool exr_depth) {
  DigestCache digests(cache_folder());
  nlohmann::json settings = pixel_settings(scene, options);
  if (exr_depth) settings["exr_depth"] = true;  // the same file names, other contents
  const RunIdentity id = run_identity(scene, settings, PYRO_VERSION, digests);
  return {{"digest", id.digest}, {"parts", id.parts}, {"scene_file", scene_file}};
}

}  // namespace pyro
