#pragma once
// Fire is a light (docs/lighting.md): in the light phase, every fire particle of the explosion's
// media becomes a point emitter, and a few point lights are clustered from them
// (engine/math/point_light_clusters.h) into the FireLights resource that the explosion's and the
// opaque pass's shaders read. They flicker with the fire: the particles' temperatures, opacities
// and sizes change every frame, and so do the lights.
#include <vector>

#include "components/explosion_shading.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "engine/math/blackbody.h"
#include "engine/math/point_light_clusters.h"
#include "engine/math/shadow_caster.h"
#include "engine/particles/particle_pool.h"

namespace pyro {

// Every fire particle with density > 0 of `pools` as a point emitter: its position, radius and
// intensity L_e(T) A e. L_e is the fire shader's radiance at the particle's temperature (bias +
// scale T, its detail noise at its mean), A = sphere_opacity_area(r, density * opacity), and e
// the fraction of its light that leaves the media: the mean over the six axis directions of
// exp(-tau), tau the optical depth of every other caster from its centre outward (`casters`, the
// light phase's, itself among them: its own k r taken out). A dense fireball's inner particles
// are hidden by its outer ones, as its fragments are.
std::vector<PointEmitter> fire_emitters(const std::vector<const ParticlePool*>& pools,
                                        const ExplosionShading& shading, const BlackbodyTable& emission,
                                        const std::vector<ShadowCaster>& casters);

// Runs after the shadow systems; writes FireLights (empty unless the world is lit, its particles are the
// explosion's media and ShadowSettings::fire_lights > 0).
ecs::SystemDesc fire_light_system();

}  // namespace pyro
