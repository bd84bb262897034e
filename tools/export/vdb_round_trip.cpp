#include "tools/export/vdb_round_trip.h"

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/io/scratch_folder.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "engine/io/vdb_reader.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/reference/volume_reference.h"
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tools/export/vdb_export.h"
#include "tools/export/vdb_sequence_naming.h"
#include "tools/export/world_media.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A folder of its own under the system's temporary folder, removed with what it holds.
// The frame's particles of `scene` (run to `frame`), white: their opacity is what is compared.
ParticlePool white_particles(const SceneDescription& scene, int frame, bool gaussians_only) {
  RuntimeOptions o;
  o.readback = false;
  o.width_override = o.height_override = 16;
  const std::unique_ptr<SceneRuntime> runtime = open_runtime(scene, o);
  const uint64_t target = runtime->sequencer().runtime_frame(frame);
  while (runtime->frame() <= target) runtime->simulate_step();
  if (gaussians_only)
    for (const MediaSample& s : world_media(runtime->world()))
      if (s.field.shape != CasterShape::gaussian)
        throw UserError(scene.file, "", "a scene of Gaussian splats for the round trip (the CPU reference draws those), "
                                        "found spheres or anisotropic particles");
  ParticlePool pool = gather_particles(runtime->world());
  for (size_t i = 0; i < pool.size(); ++i) pool.r[i] = pool.g[i] = pool.b[i] = 1.0f;
  return pool;
}

CameraFrame round_trip_camera(const CameraDescription& c, int width, int height) {
  return make_camera_frame(c.position, c.target, c.up, c.fov_y_deg, c.near, c.far, width, height);
}

RgbImage opacity_image(const ParticlePool& pool, const CameraFrame& camera) {
  return render_particles_reference(pool, camera, glm::dvec3(0.0));
}

// The exported grid as read back by the VDB reader, ray marched (trilinear, a tenth of a voxel a
// step) as an opacity image: white emission-absorption (albedo 1, no sun, ambient 1) over black.
RgbImage grid_opacity_image(const std::string& file, const CameraFrame& camera) {
  const DenseGrid grid = read_vdb_grid(file, {"density", -1});
  VolumeMedium white;
  white.extinction = 1.0;
  white.albedo = 1.0;
  white.light_color = glm::dvec3(0.0);
  white.ambient = glm::dvec3(1.0);
  white.background = glm::dvec3(0.0);
  return render_volume_reference(grid, std::vector<float>(grid.size(), 0.0f), camera, white, 0.1);
}

struct ImageDifference {
  double max = 0.0, rmse = 0.0;
};

ImageDifference difference(const RgbImage& a, const RgbImage& b) {
  ImageDifference d;
  double squares = 0.0;
  for (size_t i = 0; i < a.rgb.size(); i += 3) {
    const double e = std::abs(double(a.rgb[i]) - double(b.rgb[i]));
    d.max = std::max(d.max, e);
    squares += e * e;
  }
  d.rmse = std::sqrt(squares / double(std::max<size_t>(a.rgb.size() / 3, 1)));
  return d;
}

// The scene that imports the exported frame: the original's camera, the file at its own origin.
SceneDescription import_scene(const fs::path& folder, const std::string& file, const SceneDescription& original,
                              double import_error) {
  const fs::path path = folder / "imported.json";
  const CameraDescription& c = original.camera;
  const nlohmann::json scene = {
      {"name", "imported"},
      {"camera", {{"position", {c.position.x, c.position.y, c.position.z}}, {"target", {c.target.x, c.target.y, c.target.z}}}},
      {"volumes", {{{"file", file}, {"extinction", 1}, {"anchor", "origin"}, {"error", import_error}}}}};
  std::ofstream(path) << scene.dump();
  return load_scene(path.string());
}

}  // namespace

VdbRoundTrip measure_vdb_round_trip(const VdbRoundTripOptions& o, const NoteSink& note) {
  const SceneDescription original = load_scene(o.scene);
  ScratchFolder work("pyro-export-round-trip");
  VdbExportOptions e;
  e.scene = o.scene;
  e.out = (work.path / "vdb").string();
  e.frames = std::to_string(o.frame) + ":" + std::to_string(o.frame);
  e.name = "frame";
  e.error = o.error;
  e.voxel_size = o.voxel_size;
  const VdbExportReport exported = run_vdb_export(e, note, nullptr);
  const ParticlePool before = white_particles(original, o.frame, true);
  const auto t0 = Clock::now();
  const ParticlePool after = white_particles(
      import_scene(work.path, "vdb/" + vdb_frame_file_name("frame", o.frame), original, o.import_error), 0, false);
  const double import_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  const CameraFrame camera = round_trip_camera(original.camera, o.width, o.height);
  const RgbImage truth = opacity_image(before, camera);
  const ImageDifference grid = difference(
      truth, grid_opacity_image((work.path / "vdb" / vdb_frame_file_name("frame", o.frame)).string(), camera));
  const ImageDifference imported = difference(truth, opacity_image(after, camera));
  VdbRoundTrip r;
  r.json = {{"scene", o.scene}, {"frame", o.frame}, {"export", exported.json}, {"import_error", o.import_error},
            {"particles", before.size()}, {"import_particles", after.size()}, {"import_seconds", import_seconds},
            {"width", o.width}, {"height", o.height}, {"grid_opacity_max_difference", grid.max},
            {"grid_opacity_rmse", grid.rmse}, {"opacity_max_difference", imported.max},
            {"opacity_rmse", imported.rmse}};
  r.text = exported.text + format_text(
      "opacity images %dx%d against the particles' CPU reference:\n"
      "  the exported grid, ray marched: largest difference %.4f, RMSE %.5f\n"
      "  imported again (extinction 1, error %g; %zu particles -> %zu in %.2f s): largest difference %.4f, RMSE %.5f\n",
      o.width, o.height, grid.max, grid.rmse, o.import_error, before.size(), after.size(), import_seconds,
      imported.max, imported.rmse);
  return r;
}

}  // namespace pyro
