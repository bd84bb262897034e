#pragma once
// Six-way lightmaps (Unity VFX Graph's "Six-way Smoke Lit" output; Unity blog, "Realistic smoke
// lighting with 6-way lighting in VFX Graph", 2022): a sprite of smoke baked under six lights, one
// along each axis of the sprite's camera-facing frame, and relit at run time under any light by
// blending the six.
//
// The frame (x right, y up, z towards the viewer, as the engine's camera space) and the faces,
// each named by where its light is, as Unity names them:
//   right: light at +x   top: light at +y    back: light behind the smoke (at -z, back-lit)
//   left:  light at -x   bottom: light at -y front: light at the viewer's side (+z)
// Unity's channel packing (VFX Graph manual, "Six-way lighting", Lightmap channel mapping):
// lightmap A = (right, top, back, alpha), lightmap B = (left, bottom, front, emissive).
//
// The blend (Unity's URP SixWayLighting.hlsl, SixWayLightBlend; HDRP's likewise): with
// w = the unit vector towards the light in that frame (Unity's local frame has z = -normal, away
// from the viewer, so its "back" is our -z),
//   lighting = sum over the axes a of w_a^2 * (w_a >= 0 ? positive face : negative face).
// The weights are the squared components, not max(0, +-w_a): they sum to 1 for every direction,
// so an axis light gives its face exactly and a diagonal (+-1, +-1, +-1)/sqrt(3) the mean of its
// three faces.
#include <array>
#include <glm/vec3.hpp>

namespace pyro {

// In the order of the channels: A.r, A.g, A.b, then B.r, B.g, B.b.
enum class SixWayFace { right = 0, top = 1, back = 2, left = 3, bottom = 4, front = 5 };
inline constexpr int kSixWayFaces = 6;

using SixWayValues = std::array<float, kSixWayFaces>;  // indexed by SixWayFace

// The unit direction towards face f's light in the camera-facing frame (above).
glm::vec3 six_way_towards_light(SixWayFace f);

// Each face's weight for a light towards `towards_light` (camera-facing frame; normalised here,
// not zero): the squared components, each on the face of its sign (above).
SixWayValues six_way_weights(const glm::vec3& towards_light);

// The blended lighting: sum over the faces of weight times value.
float six_way_relight(const SixWayValues& faces, const glm::vec3& towards_light);

}  // namespace pyro
