#include "tools/bench/cycles_scene_request.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "components/explosion_shading.h"
#include "components/light_block.h"
#include "components/mesh_instance.h"
#include "components/render_settings.h"
#include "components/shadow_settings.h"
#include "components/view.h"
#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/io/vdb_reader.h"
#include "engine/math/blackbody.h"
#include "tools/export/column_error.h"
#include "tools/export/media_vdb.h"
#include "tools/export/voxel_size_choice.h"
#include "tools/export/world_media.h"

namespace pyro {

namespace {

nlohmann::json world_vec3_json(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json camera_json(const CameraFrame& f) {
  return {{"position", world_vec3_json(glm::dvec3(f.eye))},
          {"target", world_vec3_json(glm::dvec3(f.eye) + glm::dvec3(f.forward))},
          {"up", world_vec3_json(glm::dvec3(f.up))},
          {"fov_y_deg", double(f.fov_y_rad) * 180.0 / M_PI}};
}

void add_lights(const LightBlock& block, CyclesScene& out) {
  nlohmann::json suns = nlohmann::json::array();
  for (int i = 0; i < block.counts.x; ++i)
    suns.push_back({{"travel", world_vec3_json(glm::dvec3(block.sun_travel[i]))},
                    {"radiance", world_vec3_json(glm::dvec3(block.sun_radiance[i]))}});
  out.request["suns"] = suns;
  out.request["ambient"] = world_vec3_json(glm::dvec3(block.ambient));
  if (block.counts.x > 0) out.toward_key = glm::dvec3(block.sun_toward[0]);
  if (block.counts.x > 1) out.approximations.push_back("suns after the first are unshadowed in the engine");
  if (block.counts.y > 0) out.approximations.push_back("the engine lights with the fire's clustered point lights, Cycles with the glowing medium itself");
}

void add_meshes(ecs::World& world, CyclesScene& out) {
  nlohmann::json meshes = nlohmann::json::array();
  world.each<const MeshInstance>([&](ecs::Entity e, const MeshInstance& m) {
    if (!m.geometry) return;
    const MeshData& d = m.geometry->data;
    const glm::mat3 rotation = m.placement.rotation();
    std::vector<float> positions, normals;
    std::vector<glm::dvec3> world_points;
    for (size_t i = 0; i < d.positions.size(); ++i) {
      const glm::vec3 p = m.placement.apply(d.positions[i]);
      const glm::vec3 n = glm::normalize(rotation * d.normals[i]);
      world_points.emplace_back(p);
      positions.insert(positions.end(), {p.x, p.y, p.z});
      normals.insert(normals.end(), {n.x, n.y, n.z});
    }
    for (size_t t = 0; t + 2 < d.indices.size(); t += 3)
      out.triangles.push_back({world_points[d.indices[t]], world_points[d.indices[t + 1]], world_points[d.indices[t + 2]]});
    meshes.push_back({{"name", "mesh_" + std::to_string(e.index)},
                      {"albedo", world_vec3_json(glm::dvec3(m.color))},
                      {"positions", positions},
                      {"normals", normals},
                      {"indices", d.indices}});
  });
  out.request["meshes"] = meshes;
}

// The explosion's media as its shader draws them (sphere_billboard.frag): dust and smoke scatter
// with their medium's albedo; fire scatters nothing and emits the black-body radiance at its
// temperature, mapped by the shading's scale and bias (its detail noise averaged out).
void explosion_media(const ExplosionShading& shading, std::vector<MediaSample>& samples) {
  const BlackbodyTable table =
      blackbody_emission_table(shading.fire_t_min, shading.fire_t_max, shading.fire_emission, 256);
  for (MediaSample& s : samples) {
    if (!s.medium) continue;
    s.color = glm::vec3(shading.media[size_t(*s.medium)].albedo);
    if (s.fire) s.emission = sample_blackbody_rgb(table, shading.fire_bias + shading.fire_scale * s.temperature);
  }
}

// Each sample's albedo and emission as the engine draws it; returns the phase function's g.
double scattering_of(ecs::World& world, std::vector<MediaSample>& samples, CyclesScene& out) {
  const RenderSettings* settings = world.try_resource<const RenderSettings>();
  const ShadowSettings* shadows = world.try_resource<const ShadowSettings>();
  if (settings && settings->shading == ParticleShading::explosion) {
    const ExplosionShading shading = world.has_resource<ExplosionShading>() ? world.resource<ExplosionShading>()
                                                                             : ExplosionShading{};
    explosion_media(shading, samples);
    out.approximations.push_back("explosion media scatter with Cornette-Shanks in the engine, Henyey-Greenstein here");
    return shading.media[size_t(ParticleMedium::smoke)].g;
  }
  for (MediaSample& s : samples)
    if (s.fire) s.color = glm::vec3(0.0f);
  if (shadows && shadows->scattering.octaves.octaves > 1)
    out.approximations.push_back("the engine's octaves stand for Cycles' multiple scattering");
  return shadows ? shadows->scattering.anisotropy : 0.0;
}

bool colours_vary(const std::vector<MediaSample>& samples) {
  for (const MediaSample& s : samples)
    if (glm::length(s.color - samples.front().color) > 1e-3f) return true;
  return false;
}

void add_media(ecs::World& world, const CyclesSceneOptions& o, CyclesScene& out) {
  out.request["media"] = nullptr;
  std::vector<MediaSample> samples = world_media(world);
  out.particles = int(samples.size());
  if (samples.empty()) return;
  const double g = scattering_of(world, samples, out);
  const bool emits = std::any_of(samples.begin(), samples.end(),
                                 [](const MediaSample& s) { return glm::length(s.emission) > 0.0f; });
  const VoxelSizeChoice choice = choose_voxel_size(samples, 0.75 * o.voxel_error, o.max_voxels);
  if (!choice.fits)
    throw UserError("", "--voxel-error",
                    format_text("an error the media's grid of at most %llu voxels can meet (%.4g at voxel %g)",
                                (unsigned long long)o.max_voxels, choice.error.opacity_max, choice.voxel));
  const bool vary = colours_vary(samples);
  out.media = voxelize_media(samples, media_box(samples, choice.voxel), {false, vary, emits});
  out.voxel_error = measure_column_error(samples, out.media).opacity_max;
  write_vdb_grids(o.vdb, media_vdb_grids(out.media));
  out.request["media"] = {{"vdb", o.vdb},
                          {"anisotropy", g},
                          {"albedo", world_vec3_json(glm::dvec3(samples.front().color))},
                          {"color_grid", vary ? "color" : ""},
                          {"emission_grid", emits ? "emission" : ""}};
}

}  // namespace

CyclesScene cycles_scene_of(ecs::World& world, const CyclesSceneOptions& options) {
  CyclesScene out;
  out.camera = world.resource<View>().eyes.at(0);
  out.request["camera"] = camera_json(out.camera);
  out.request["width"] = out.camera.width;
  out.request["height"] = out.camera.height;
  add_lights(world.resource<LightBlock>(), out);
  add_meshes(world, out);
  add_media(world, options, out);
  return out;
}

}  // namespace pyro
