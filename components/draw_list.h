#pragma once
// Resource: every particle to draw this frame, back to front. Written by the sorting system,
// read by the billboard renderers and the tools. A list comes in one of two forms:
//  - gathered: the attribute arrays, in draw order (the sphere and explosion billboards, and
//    lists made by hand);
//  - indexed: `order`, the draw order as indices into the frame's packed particle records
//    (EyeDrawLists::records), which the Gaussian splats' vertex shader reads itself, so nothing
//    is gathered on the CPU.
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

namespace pyro {

struct DrawList {
  std::vector<glm::vec4> center_radius;  // xyz world position, w radius
  std::vector<glm::vec4> color_density;  // rgb linear colour, a density rho
  // Explosion media (Umenhoffer et al. 2006): temperature (K), opacity (0-1), medium
  // (components/particle_medium.h, as a float), and a per-particle detail-window key in [0, 1).
  // Read only by the explosion shading; empty otherwise.
  std::vector<glm::vec4> medium;
  // Indexed form: record k of the draw order is EyeDrawLists::records[2 order[k]] (centre and
  // radius) and [2 order[k] + 1] (colour and density). Empty in the gathered form.
  std::vector<uint32_t> order;

  bool indexed() const { return !order.empty(); }
  size_t size() const { return indexed() ? order.size() : center_radius.size(); }
};

// Resource: one DrawList per rendered view (billboards facing the viewpoint are ordered by
// distance to each eye; facing the viewplane, every eye shares one order), and the records the
// indexed lists point into.
struct EyeDrawLists {
  std::vector<DrawList> eyes;
  // Two vec4s per particle (centre-radius, colour-density), every set's particles one set after
  // another; the same for every eye.
  std::vector<glm::vec4> records;
};

// Eye `eye`'s list in the gathered form (a copy; an indexed list is gathered from the records).
inline DrawList gathered_draw_list(const EyeDrawLists& lists, size_t eye) {
  const DrawList& list = lists.eyes.at(eye);
  if (!list.indexed()) return list;
  DrawList out;
  out.center_radius.resize(list.order.size());
  out.color_density.resize(list.order.size());
  for (size_t k = 0; k < list.order.size(); ++k) {
    out.center_radius[k] = lists.records.at(2 * size_t(list.order[k]));
    out.color_density[k] = lists.records.at(2 * size_t(list.order[k]) + 1);
  }
  return out;
}

}  // namespace pyro
