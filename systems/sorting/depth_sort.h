#pragma once
// Sort phase, the `sorting` system: lists the particles of every ParticleSet in one DrawList
// per rendered view (the eye frames the stereo_camera system put in View), back to front,
// indexed for Gaussian splats and gathered for the other billboards (components/draw_list.h).
// Billboards facing the viewplane are ordered by view depth (the distance along the view axis),
// which is the same for both eyes of a parallel-axis stereo pair, so the eyes share one sort.
// Billboards facing the viewpoint are ordered by distance to each eye.
// The order is a strict total order: key descending, then the set's entity index, then the
// particle's id, so equal keys never swap between frames or runs. It is found by a radix sort
// of the depths (radix_sort.h) into the order of the keys' indices; the keys are not moved.
// Only what the views can show is listed: a particle whose bounding sphere lies outside every
// frustum the list is drawn into is left out before the sort (it would draw nothing).
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "components/draw_list.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "engine/math/camera_math.h"
#include "engine/math/view_frustum.h"
#include "systems/sorting/radix_sort.h"
#include "systems/sorting/sort_key.h"

namespace pyro {

// Sorts keys in place with back_to_front (radix_sort.h: the result depends neither on the input
// order nor on the thread count).
void sort_back_to_front(std::vector<SortKey>& keys);

enum class SortKeyKind { view_depth, eye_distance };

// A particle's bounding sphere for culling, in radii: the Gaussian splat's quad reaches sqrt(2)
// radii from its centre, a spherical billboard's sphere one; twice the radius holds both.
inline constexpr float kCullRadii = 2.0f;

class ParticlePool;

// Milliseconds of the sorting system's stages in its last run, summed over the draw lists it
// built: making the keys, packing the particles' instance data, ordering the keys, gathering the
// records into the lists. pyro bench scale reads them.
struct SortStageTimes {
  double keys_ms = 0.0, pack_ms = 0.0, order_ms = 0.0, gather_ms = 0.0;
};

// Resource: the sort's working space, kept between frames so that sorting allocates nothing in
// steady state (the sorting system's setup makes it).
struct SortScratch {
  std::vector<SortKey> keys;  // every particle's, the culled ones too (the sort reads those kept)
  RadixScratch radix;
  std::vector<std::pair<uint32_t, const ParticlePool*>> sets;  // (entity index, pool)
  std::vector<const ParticleLight*> lights;  // beside each set: its light, or null (unlit)
  // The gathered form's particles packed in key order, two or three vec4s each (depth_sort.cpp).
  std::vector<glm::vec4> packed;
  std::vector<uint8_t> seen;          // culling: 1 for a particle some view can show,
  std::vector<uint32_t> kept_places;  // and the keys kept, when some were not (else empty)
  SortStageTimes times;
};

// Fills `list` in the gathered form from every ParticleSet in the world, sorted for an eye at
// `eye` looking along `forward`. `with_medium`: also list.medium, which only the explosion media
// layers read (left empty otherwise, a third less to gather), and, where the sets are lit (a
// ParticleLight beside them), list.light. Culling: a particle whose bounding
// sphere (two radii) lies outside every frustum of `views` is left out, before the sort; an empty
// `views` keeps every particle. Leaving out a particle no view can show changes no image.
void build_draw_list(const ecs::World& world, const glm::vec3& eye, const glm::vec3& forward,
                     SortKeyKind kind, SortScratch& scratch, DrawList& list,
                     bool with_medium = true, std::span<const ViewFrustum> views = {});

// The indexed form (components/draw_list.h): collect_particle_sets once (the pools in entity
// order, into scratch.sets), then for each eye the order of those pools' particles, one pool after
// another, into list.order. The order is the same as build_draw_list's.
void collect_particle_sets(const ecs::World& world, SortScratch& scratch);
void order_draw_list(const glm::vec3& eye, const glm::vec3& forward, SortKeyKind kind,
                     SortScratch& scratch, DrawList& list, std::span<const ViewFrustum> views = {});

// The `sorting` system: Gaussian splats get indexed lists, the other billboards gathered ones;
// sets of different kinds (components/particle_kind.h, systems/sorting/particle_shapes.h) one
// gathered list of them all with each entry's kind (DrawList::shapes).
// Each list leaves out the particles its views cannot show (a shared list: those outside every
// eye's frustum).
// It reads View (written by stereo_camera in the camera phase), never the
// camera itself.
ecs::SystemDesc sorting_system();

}  // namespace pyro
