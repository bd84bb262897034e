#pragma once
// What a scene read from files, kept from one load to the next so that a rebuild after an edit
// (the viewer's inspector) reads again only what the edit touched: an emitter's rate re-imports
// no VDB grid and re-prepares no flipbook. load_scene_assets (RuntimeOptions::asset_cache) asks
// it for each volume and each fire's flipbook:
//  - a volume (a particle file or a VDB grid, read or imported and placed) is reused when
//    everything its loading reads is unchanged: the entry's keys that shape it (file, fallback
//    and the resolved path, grid, error, extinction, temperature grid, emission, placement), the
//    scene's lights, background and whether its media are lit, and the file's stamp (size,
//    modification time, inode). Particle sequences are not held: their frames are read while they
//    play, and what their asset step reads is one small manifest.
//  - a flipbook's prepared frames are reused when the folder, the preparation (crop, base line,
//    soften) and the stamps of the folder's files are unchanged.
// Only the entries of the last load are held: a load drops every entry it did not use.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "components/flipbook_fire.h"
#include "systems/flipbook_fire/flipbook_world.h"
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/runtime_options.h"
#include "systems/runtime/scene_runtime/scene_assets.h"

namespace pyro {

// A volume as its reading made it, and the reader's notes (which grid, which fire map).
struct LoadedVolume {
  VolumeAsset asset;
  std::vector<std::string> notes;
};

struct SceneAssetCounters {
  uint64_t volumes_loaded = 0;      // volume files read or imported
  uint64_t volumes_reused = 0;      // volumes taken from the cache instead
  uint64_t flipbooks_prepared = 0;  // flipbook folders read and prepared
  uint64_t flipbooks_reused = 0;    // prepared flipbooks taken from the cache instead
  uint64_t flipbooks_baked = 0;     // bakes of the engine's default flipbook
};

class SceneAssetCache {
 public:
  const SceneAssetCounters& counters() const { return counters_; }

  // A load: volume() and flipbooks() calls between begin_load() and end_load() make its
  // entries; end_load() drops every entry the load did not use.
  void begin_load();
  void end_load();

  // The asset of the (non-sequence) volume entry `v` of `scene`: the held one, else what
  // `read` makes of it (a particle file read or a grid imported, placed). `note` gets the
  // reader's notes either way. Not for use by two loads at once.
  VolumeAsset volume(const SceneDescription& scene, const VolumeDescription& v,
                     const std::function<LoadedVolume()>& read, const NoteSink& note);

  // load_flipbooks(fires) (fires' folders resolved), each prepared flipbook taken from the cache
  // when held.
  FlipbookAssets flipbooks(const std::vector<FlipbookFire>& fires);

  // Counts a bake of the engine's default flipbook (the front door's prepare_scene_run makes it,
  // systems/runtime/open_scene/open_scene.h, for a runtime opened with this cache).
  void count_default_bake() { ++counters_.flipbooks_baked; }

 private:
  // Keyed by what their loading reads (scene_asset_cache.cpp); next_*: the current load's.
  std::map<std::string, LoadedVolume> volumes_, next_volumes_;
  std::map<std::string, FlipbookFrames> flipbooks_, next_flipbooks_;
  SceneAssetCounters counters_;
};

}  // namespace pyro
