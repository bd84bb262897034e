#include "systems/flipbook_fire/flipbook_world.h"

#include <map>
#include <stdexcept>
#include <tuple>

#include "systems/flipbook_fire/flipbook_emission.h"
#include "systems/flipbook_fire/flipbook_layout.h"
#include "systems/flipbook_fire/flipbook_renderer.h"

namespace pyro {

FlipbookFrames read_prepared_flipbook(const FlipbookFire& fire) {
  FlipbookFrames frames = read_flipbook_folder(fire.flipbook);
  prepare_flipbook(frames, fire.preparation);
  return frames;
}

FlipbookAssets load_flipbooks(const std::vector<FlipbookFire>& fires,
                              const std::function<FlipbookFrames(const FlipbookFire&)>& prepared) {
  using Key = std::tuple<std::string, float, float, float, float, float, float>;
  std::map<Key, size_t> loaded;  // -> index into assets.frames
  FlipbookAssets assets;
  for (const FlipbookFire& fire : fires) {
    if (fire.flipbook.empty())
      throw std::invalid_argument("load_flipbooks: fire \"" + fire.name + "\" names no folder");
    const FlipbookPreparation& p = fire.preparation;
    const Key key{fire.flipbook, p.crop.x, p.crop.y, p.crop.z, p.crop.w, p.base_line, p.soften};
    auto it = loaded.find(key);
    if (it == loaded.end()) {
      assets.frames.push_back(prepared(fire));
      it = loaded.emplace(key, assets.frames.size() - 1).first;
    }
    assets.fire_frames.push_back(it->second);
  }
  return assets;
}

void add_flipbook_fires(ecs::World& world, const std::vector<FlipbookFire>& fires,
                        const FlipbookAssets& assets) {
  if (fires.empty()) return;
  if (assets.fire_frames.size() != fires.size())
    throw std::invalid_argument("add_flipbook_fires: the assets are not these fires'");
  if (!world.has_resource<FlipbookRenderer>()) world.set_resource<FlipbookRenderer>();
  FlipbookRenderer& renderer = world.resource<FlipbookRenderer>();
  std::vector<int> textures;
  for (const FlipbookFrames& frames : assets.frames) textures.push_back(renderer.add_flipbook(frames));
  for (size_t k = 0; k < fires.size(); ++k) {
    FlipbookFire fire = fires[k];
    const size_t index = assets.fire_frames[k];
    fire.texture = textures.at(index);
    fire.frame_count = static_cast<int>(assets.frames[index].rgba.size());
    fire.motion_vectors = !assets.frames[index].motion.empty();
    fire.six_way = assets.frames[index].six_way();
    fire.billboards = expand_flipbook_groups(fire);
    const ecs::Entity e = world.create();
    world.emplace<FlipbookEmission>(e, flipbook_emission(assets.frames[index], fire.blend));
    world.emplace<FlipbookFire>(e, std::move(fire));
  }
}

}  // namespace pyro
