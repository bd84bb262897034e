#pragma once
// Where a flipbook fire's billboards stand in the world this frame (Rose 2007, section 4.6): the
// whole group rotates about the axis through the base centre along the base normal so that its
// depth axis points at the viewer, and every billboard stays perpendicular to the base (it
// contains the up axis). In stereo the viewer is the mid-eye point (the mono camera), so both
// eyes see one and the same group, and the parallax between the eyes is that of real geometry.
#include <vector>

#include <glm/vec3.hpp>

#include "components/flipbook_draw_list.h"
#include "components/flipbook_fire.h"

namespace pyro {

// Faces `viewer`. When the viewer stands on the axis (straight above or below the base, where
// the thesis says the billboards become evident), `fallback_toward` projected into the base
// plane is used, and failing that any direction perpendicular to up.
FireFrame face_viewer(const glm::vec3& base, const glm::vec3& up, const glm::vec3& viewer,
                      const glm::vec3& fallback_toward);

// The quads of one fire at flipbook time step `step`, sorted back to front (by depth; ties by
// billboard order), for a flipbook of `frame_count` frames; `fraction` of the way to step + 1
// (each quad's next_frame, blend and motion_scale).
std::vector<FlipbookQuad> flipbook_quads(const FlipbookFire& fire, const FireFrame& frame,
                                         int64_t step, int frame_count, float fraction = 0.0f);

}  // namespace pyro
