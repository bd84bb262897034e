#include "systems/runtime/scene_runtime/load_scene_assets.h"

#include <utility>

#include "systems/runtime/cloud_import/scene_volume.h"
#include "systems/runtime/scene_runtime/flipbook_bake.h"
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

void load_fires(const SceneDescription& scene, SceneAssets& assets, const Notes& note,
                SceneAssetCache* cache) {
  assets.fires = scene.fires;
  for (FlipbookFire& fire : assets.fires) {
    if (!fire.flipbook.empty()) continue;
    if (cache && !default_flipbook_baked()) cache->count_default_bake();
    fire.flipbook = ensure_default_flipbook(note);
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
  load_fires(resolved.scene, assets, note, cache);
  if (cache) cache->end_load();
  return assets;
}

}  // namespace pyro
