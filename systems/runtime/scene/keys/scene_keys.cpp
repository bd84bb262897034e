// The scene file's top level, and the small objects that hang directly below it.
#include <cstdint>
#include <limits>

#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene/scene_keys.h"

namespace pyro {

const ParameterTable& output_keys() {
  static const SceneDescription d{};
  static const ParameterTable table{
      "output", "Image size, frame rate and background.",
      {integer_key("width", 1, 8192, "Image width in pixels (per eye).").with_default(d.width),
       integer_key("height", 1, 8192, "Image height in pixels.").with_default(d.height),
       number_key("fps", kPositive, "Frames per second of animation time.").with_default(d.frames_per_second),
       enum_key<OutputBackground>("background",
                                  "\"none\": frames with alpha, the media and meshes over nothing.")
           .with_default(d.output_background)}};
  return table;
}

const ParameterTable& footprint_keys() {
  static const FootprintDescription d{};
  static const ParameterTable table{
      "footprint", "The Gaussian footprint table (Johnson & McAllister 2005, eq. 4).",
      {integer_key("size", 2, 4096, "The table is size x size texels.").with_default(d.size),
       integer_key("intervals", 1, 100000, "Composite quadrature intervals along z.").with_default(d.intervals)}};
  return table;
}

const ParameterTable& budget_keys() {
  static const SceneBudget d{};
  static const ParameterTable table{
      "budget", "Resource limits checked before anything is allocated.",
      {integer_key("particles", 1, 4'000'000'000ull, "Most particles in the scene.").with_default(d.particles),
       integer_key("memory_mib", 1, 1ull << 20, "Most memory, MiB.").with_default(d.memory_bytes >> 20),
       integer_key("texture_size", 1, 65536, "Largest render target side (absent: the driver's maximum).")}};
  return table;
}

const ParameterTable& quality_keys() {
  static const ParameterTable table{
      "quality", "An image-error target that picks the layer scale, footprint size and time step.",
      {number_key("max_rmse", Range{0.0, 1.0, true, false}, "The largest image RMSE accepted.").as_required()}};
  return table;
}

const ParameterTable& scene_keys() {
  static const SceneDescription d{};
  static const ParameterTable table{
      "scene", "A Pyrocumulus scene (docs/scene_format.md).",
      {string_key("name", "Scene name, for reports.").with_default(d.name),
       integer_key("seed", 0, std::numeric_limits<std::uint64_t>::max(), "Every random stream derives from it.")
           .with_default(d.seed),
       object_key("output", output_keys(), "Image size, frame rate and background."),
       vec3_key("background", kNonNegative, "Linear RGB sky colour.").with_default(d.background),
       object_key("camera", camera_keys(), "The viewpoint."),
       object_key("light", light_keys(), "The directional and ambient light; not with lights."),
       object_key("footprint", footprint_keys(), "The Gaussian footprint table."),
       object_key("render", render_keys(), "How the particles are drawn."),
       objects_key("clouds", cloud_keys(), "Particle clouds."),
       objects_key("meshes", mesh_keys(), "Opaque scenery."),
       objects_key("volumes", volume_keys(), "Volumes read from files."),
       object_key("environment", environment_keys(), "What all emitters share."),
       objects_key("emitters", emitter_keys(), "Explosion particle emitters."),
       objects_key("fires", fire_keys(), "Flipbook fires."),
       object_key("budget", budget_keys(), "Resource limits."),
       object_key("quality", quality_keys(), "An image-error target."),
       object_key("shadows", shadow_keys(), "Lit particle media (absent: unlit)."),
       objects_key("lights", light_source_keys(), "Any number of lights; not with light."),
       string_key("$schema", "The JSON Schema of this file, for editors; ignored by the engine.")}};
  return table;
}

}  // namespace pyro
