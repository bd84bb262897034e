#pragma once
// A flipbook fire (components/flipbook_fire.h) as light (docs/lighting.md): each of its
// billboards is a point emitter at the middle of its card, of intensity s A L_f, s the
// billboard's colour scale, A = width x height its card's area and L_f the mean radiance of the
// frame it shows at that time (components/flipbook_emission.h). The cards turn to face the viewer,
// so the fire is taken as a flame that shows the same area from every side: the same model as
// the explosion's fire particles (intensity = radiance x the area it shows). The emitters sit on
// the fire's axis, half a card above its base (the cards' offsets across and in depth turn with
// the viewer and are left out); they flicker as the frames play, and all together as the flame
// puffs (flicker_of, engine/math/flame_flicker.h), as its billboards do.
#include <vector>

#include "components/flipbook_emission.h"
#include "components/flipbook_fire.h"
#include "engine/math/point_light_clusters.h"

namespace pyro {

std::vector<PointEmitter> flipbook_fire_emitters(const FlipbookFire& fire, const FlipbookEmission& emission,
                                                 double seconds);

}  // namespace pyro
