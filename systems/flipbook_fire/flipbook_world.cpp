#include "systems/flipbook_fire/flipbook_world.h"

#include <map>
#include <tuple>

#include "systems/flipbook_fire/flipbook_folder.h"
#include "systems/flipbook_fire/flipbook_bake.h"
#include "systems/flipbook_fire/flipbook_layout.h"
#include "systems/flipbook_fire/flipbook_renderer.h"

namespace pyro {

void add_flipbook_fires(ecs::World& world, const std::vector<FlipbookFire>& fires) {
  if (fires.empty()) return;
  if (!world.has_resource<FlipbookRenderer>()) world.set_resource<FlipbookRenderer>();
  FlipbookRenderer& renderer = world.resource<FlipbookRenderer>();
  using Key = std::tuple<std::string, float, float, float, float, float, float>;
  std::map<Key, std::pair<int, int>> loaded;  // -> texture, frame count
  for (const FlipbookFire& description : fires) {
    FlipbookFire fire = description;
    if (fire.flipbook.empty()) fire.flipbook = ensure_default_flipbook();
    const FlipbookPreparation& p = fire.preparation;
    const Key key{fire.flipbook, p.crop.x, p.crop.y, p.crop.z, p.crop.w, p.base_line, p.soften};
    auto it = loaded.find(key);
    if (it == loaded.end()) {
      FlipbookFrames frames = read_flipbook_folder(fire.flipbook);
      prepare_flipbook(frames, p);
      it = loaded.emplace(key, std::make_pair(renderer.add_flipbook(frames),
                                              static_cast<int>(frames.rgba.size()))).first;
    }
    fire.texture = it->second.first;
    fire.frame_count = it->second.second;
    fire.billboards = expand_flipbook_groups(fire);
    world.emplace<FlipbookFire>(world.create(), std::move(fire));
  }
}

}  // namespace pyro
