#pragma once
// Mesh shadows: the meshes (but the ground planes, which receive only) rasterised into a
// light-space depth grid (components/mesh_shadow.h), nearest surface per texel centre, once a
// frame for every eye, like the media's opacity shadow map beside it. A receiver at texture
// depth z is in shadow where z exceeds the grid's depth plus a bias; filtered over the four
// nearest texels (percentage-closer filtering, as GL's shadow samplers do), its visibility falls
// from 1 to 0 across one texel at a shadow's edge.
#include <vector>

#include <glm/vec3.hpp>

#include "components/mesh_instance.h"
#include "components/mesh_shadow.h"
#include "engine/ecs/schedule.h"

namespace pyro {

// Whether a mesh of this kind casts shadows (every kind but the ground plane).
bool casts_shadow(MeshKind kind);

// The grid of `instances`' casters for light travelling along `light_travel` (not zero), `across`
// texels on its longer side across the light, fitted to the casters with one empty texel beyond
// them, its depth range holding every instance (receivers too). `out.version` is incremented;
// no casters: out is emptied.
void build_mesh_shadow_map(const std::vector<MeshInstance>& instances, const glm::dvec3& light_travel,
                           int across, MeshShadow& out);

// How much of the key light reaches world point p past the meshes, in [0, 1]: the bilinear
// filter of the four nearest texels' tests z(p) <= depth + bias (bias in texels' sides of depth),
// as the opaque pass samples it. Outside the grid, or an empty one: 1.
double mesh_visibility(const MeshShadow& shadow, const glm::vec3& p, double bias_texels = 1.0);

// The meshes' shadow at p as an optical depth: -ln mesh_visibility, at most kMeshShadowDepth
// (components/mesh_shadow.h); 0 outside the shadow or without casters.
double mesh_shadow_depth(const MeshShadow& shadow, const glm::vec3& p, double bias_texels = 1.0);

// The light phase's mesh_shadow system: with a ShadowSettings resource whose method is not
// none and a key light that shines, the world's MeshShadow from its MeshInstances, rebuilt only
// when the instances or the light changed.
ecs::SystemDesc mesh_shadow_system();

}  // namespace pyro
