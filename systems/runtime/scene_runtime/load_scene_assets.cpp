#include "systems/runtime/scene_runtime/load_scene_assets.h"

#include <utility>

#include "engine/core/user_error.h"
#include "systems/runtime/cloud_import/scene_volume.h"
#include "systems/runtime/scene_runtime/default_flipbook.h"
#include "systems/runtime/scene_runtime/mesh_geometry.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"
#include "systems/runtime/scene_runtime/scene_asset_cache.h"
#include "systems/volume_sequence/sequence_asset.h"

namespace pyro {

namespace {

struct Notes {
  SceneAssets& assets;
  const NoteSink& sink;
  void operator()(const std::string& note) const {
    assets.notes.push_back(note);
    if (sink) sink(note);
  }
};

std::string volume_file_note(const SceneDescription& scene, const VolumeDescription& v) {
  const std::string place = scene.file + ": " + v.pointer + ": ";
  if (v.used_fallback)
    return place + "volume file \"" + v.file + "\" not found; using the fallback \"" + v.path + "\"";
  return place + "using volume file \"" + v.path + "\"";
}

// A particle sequence: nothing of its frames read yet; its pool sized for the largest drawn frame.
VolumeAsset sequence_volume(const SceneDescription& scene, const VolumeDescription& v) {
  SequenceAsset s = load_sequence_asset(scene, v);
  return {ParticlePool(s.capacity), {}, VolumeSource{v.path, v.used_fallback, s.active_voxels, s.capacity},
          std::move(s.sequence)};
}

// A particle file read or a VDB grid imported, placed, with the reader's notes.
LoadedVolume read_volume(const SceneDescription& scene, const VolumeDescription& v) {
  SceneVolume loaded = load_scene_volume(scene, v);
  LoadedVolume out;
  if (!loaded.note.empty()) out.notes.push_back(v.path + ": " + loaded.note);
  if (!loaded.fire_note.empty()) out.notes.push_back(v.path + ": " + loaded.fire_note);
  const uint64_t count = loaded.particles.size() + loaded.anisotropic.size();
  out.asset = {to_particle_pool(loaded.particles), std::move(loaded.anisotropic),
               VolumeSource{v.path, v.used_fallback, loaded.active_voxels, count}};
  return out;
}

void load_volumes(const SceneDescription& scene, SceneAssets& assets, const Notes& note,
                  SceneAssetCache* cache) {
  for (const VolumeDescription& v : scene.volumes) {
    note(volume_file_note(scene, v));
    if (v.kind == VolumeFileKind::sequence) {
      assets.volumes.push_back(sequence_volume(scene, v));
      continue;
    }
    if (cache) {
      assets.volumes.push_back(cache->volume(scene, v, [&] { return read_volume(scene, v); }, note));
      continue;
    }
    LoadedVolume loaded = read_volume(scene, v);
    for (const std::string& n : loaded.notes) note(n);
    assets.volumes.push_back(std::move(loaded.asset));
  }
}

void load_meshes(const SceneDescription& scene, SceneAssets& assets, const Notes& note) {
  for (const MeshDescription& m : scene.meshes) {
    if (m.kind != MeshKind::file) {
      assets.meshes.push_back(nullptr);
      continue;
    }
    assets.meshes.push_back(file_geometry(scene, m));
    note(scene.file + ": " + m.pointer + ": read " + std::to_string(assets.meshes.back()->data.triangle_count()) +
         " triangles from mesh file \"" + m.path + "\"");
  }
}

// A fire without a `flipbook` plays the engine's default one, baked before the run opened (the
// front door's prepare_scene_run, systems/runtime/open_scene/open_scene.h): never baked here.
void load_fires(const SceneDescription& scene, SceneAssets& assets, SceneAssetCache* cache) {
  assets.fires = scene.fires;
  for (size_t i = 0; i < assets.fires.size(); ++i) {
    FlipbookFire& fire = assets.fires[i];
    if (!fire.flipbook.empty()) continue;
    fire.flipbook = default_flipbook_folder();
    if (!default_flipbook_baked())
      throw UserError(fire.flipbook, "",
                      "expected a baked default flame flipbook: scenes opened through the front "
                      "door (systems/runtime/open_scene/open_scene.h) bake it first, as does the "
                      "build's default_flipbook target; found no flipbook.json, for the fire at "
                      "/fires/" + std::to_string(i) + " of " + scene.file + " (no `flipbook` named)");
  }
  assets.flipbooks = cache ? cache->flipbooks(assets.fires) : load_flipbooks(assets.fires);
}

}  // namespace

SceneAssets load_scene_assets(const ResolvedScene& resolved, const NoteSink& on_note,
                              SceneAssetCache* cache) {
  SceneAssets assets;
  const Notes note{assets, on_note};
  if (cache) cache->begin_load();
  load_meshes(resolved.scene, assets, note);
  load_volumes(resolved.scene, assets, note, cache);
  if (!assets.volumes.empty()) {
    uint64_t volume_particles = 0;
    for (const VolumeAsset& v : assets.volumes) volume_particles += v.source.particles;
    check_resolved_budget(resolved, volume_particles);
  }
  load_fires(resolved.scene, assets, cache);
  if (cache) cache->end_load();
  return assets;
}

}  // namespace pyro
