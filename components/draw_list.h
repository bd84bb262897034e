#pragma once
// Resource: every particle to draw this frame, back to front. Written by the sorting system,
// read by the billboard renderers and the tools. A list comes in one of two forms:
//  - gathered: the attribute arrays, in draw order (the sphere and explosion billboards, and
//    lists made by hand);
//  - indexed: `order`, the draw order as indices into the particle pools themselves
//    (EyeDrawLists::pools, one after another), whose attribute arrays the Gaussian splats' vertex
//    shader reads itself, so nothing is gathered or packed on the CPU;
//  - ordered on the GPU: `on_gpu`, with `gpu_request` saying how; the compute shaders
//    (systems/gpu_sorting) make the indexed order when the list is drawn, so the CPU never
//    holds it (size() is 0 on the CPU).
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/math/view_frustum.h"
#include "components/particle_light.h"
#include "components/render_modes.h"
#include "engine/particles/particle_pool.h"

namespace pyro {

// How a list's particles are ordered, for the GPU to do it (systems/gpu_sorting): the sorting
// system's order for an eye at `eye` looking along `forward`, by view depth or by distance to the
// eye, culled against `views` (none: nothing culled).
struct GpuOrderRequest {
  glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};
  bool by_eye_distance = false;
  std::vector<ViewFrustum> views;
};

struct DrawList {
  std::vector<glm::vec4> center_radius;  // xyz world position, w radius
  std::vector<glm::vec4> color_density;  // rgb linear colour, a density rho
  // Explosion media (Umenhoffer et al. 2006): temperature (K), opacity (0-1), medium
  // (components/particle_medium.h, as a float), and a per-particle detail-window key in [0, 1).
  // Read only by the explosion shading; empty otherwise.
  std::vector<glm::vec4> medium;
  // Lit explosion media (docs/lighting.md): each particle's ParticleLight::others_depth (the other
  // particles' optical depth toward the sun at its centre, and its gradient). Empty: unlit.
  std::vector<glm::vec4> light;
  // Indexed form: entry k of the draw order is particle order[k] of EyeDrawLists::pools taken one
  // after another. Empty in the gathered form.
  std::vector<uint32_t> order;
  // The Gaussian splats' lists carry how the GPU would order them (when the key fits its
  // layout, systems/sorting/gpu_key_layout.h); with `on_gpu` the GPU does, and `order` is empty.
  std::optional<GpuOrderRequest> gpu_request;
  bool on_gpu = false;
  // Sets of different kinds in one list (components/particle_kind.h), gathered form only: each
  // entry's kind, so that particles of every kind blend in the one back-to-front order. Empty:
  // every entry is of the kind its renderer draws.
  std::vector<ParticleShape> shapes;

  bool indexed() const { return !order.empty(); }
  size_t size() const { return indexed() ? order.size() : center_radius.size(); }
};

// Resource: one DrawList per rendered view (billboards facing the viewpoint are ordered by
// distance to each eye; facing the viewplane, every eye shares one order), and the pools the
// indexed lists point into.
struct EyeDrawLists {
  std::vector<DrawList> eyes;
  // Every ParticleSet's pool in entity-index order, as the sorting system saw them: valid until
  // a pool changes (the next frame's spawn and simulate phases).
  std::vector<const ParticlePool*> pools;
  // Beside each pool, the light phase's light for its particles (components/particle_light.h), or
  // null: unlit, the pool's colours as they are. The Gaussian splats read it here (the billboard
  // renderer's SplatLighting); the explosion's gathered lists carry it in DrawList::light.
  std::vector<const ParticleLight*> lights;
};

// Eye `eye`'s list in the gathered form (a copy; an indexed list is gathered from the pools, with
// their colours as they are: lit splats are lit as they are drawn, billboard_renderer.h).
inline DrawList gathered_draw_list(const EyeDrawLists& lists, size_t eye) {
  const DrawList& list = lists.eyes.at(eye);
  if (!list.indexed()) return list;
  std::vector<size_t> ends;  // where each pool's particles end among all of them
  for (const ParticlePool* pool : lists.pools) ends.push_back((ends.empty() ? 0 : ends.back()) + pool->size());
  DrawList out;
  for (const uint32_t k : list.order) {
    const size_t j = size_t(std::upper_bound(ends.begin(), ends.end(), size_t(k)) - ends.begin());
    const ParticlePool& p = *lists.pools.at(j);
    const size_t i = k - (j == 0 ? 0 : ends[j - 1]);
    out.center_radius.push_back({p.px.at(i), p.py[i], p.pz[i], p.radius[i]});
    out.color_density.push_back({p.r[i], p.g[i], p.b[i], p.density[i]});
  }
  return out;
}

}  // namespace pyro
