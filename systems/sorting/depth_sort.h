#pragma once
// Sort phase, the `sorting` system: gathers every particle of every ParticleSet into one
// DrawList per rendered view (the eye frames the stereo_camera system put in View), back to
// front. Billboards facing the viewplane are ordered by view depth (the distance along
// the view axis), which is the same for both eyes of a parallel-axis stereo pair, so the eyes
// share one sort. Billboards facing the viewpoint are ordered by distance to each eye.
// The order is a strict total order: key descending, then the set's entity index, then the
// particle's id, so equal keys never swap between frames or runs. It is found by a radix sort
// of the depths (radix_sort.h) into the order of the keys' indices; the keys are not moved.
#include <cstdint>
#include <utility>
#include <vector>

#include "components/draw_list.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "engine/math/camera_math.h"
#include "systems/sorting/radix_sort.h"
#include "systems/sorting/sort_key.h"

namespace pyro {

// Sorts keys in place with back_to_front (radix_sort.h: the result depends neither on the input
// order nor on the thread count).
void sort_back_to_front(std::vector<SortKey>& keys);

enum class SortKeyKind { view_depth, eye_distance };

class ParticlePool;

// Resource: the sort's working space, kept between frames so that sorting allocates nothing in
// steady state (the sorting system's setup makes it).
struct SortScratch {
  std::vector<SortKey> keys;
  RadixScratch radix;
  std::vector<std::pair<uint32_t, const ParticlePool*>> sets;  // (entity index, pool)
};

// Fills `list` from every ParticleSet in the world, sorted for an eye at `eye` looking along
// `forward`.
void build_draw_list(const ecs::World& world, const glm::vec3& eye, const glm::vec3& forward,
                     SortKeyKind kind, SortScratch& scratch, DrawList& list);

// The `sorting` system: reads View (written by stereo_camera in the camera phase), never the
// camera itself.
ecs::SystemDesc sorting_system();

}  // namespace pyro
