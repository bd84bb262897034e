#pragma once
// One frame of a six-way bake as planes of floats, and its two 8-bit textures in Unity's packing
// (six_way_basis.h): A = (right, top, back, alpha), B = (left, bottom, front, emissive), linear
// values (not sRGB-encoded: they are light, blended in the shader), top row first.
//
// The faces are stored straight (not premultiplied by alpha): the lighting of the medium where it
// is, as Unity's shader multiplies the blended lighting by the sprite's alpha when it blends it.
// A relit frame over black is therefore  light_color * six_way_relight(faces, w) * alpha.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "systems/runtime/reference/rgb_image.h"
#include "systems/flipbook_fire/six_way_basis.h"

namespace pyro {

struct SixWayFrame {
  int width = 0, height = 0;
  std::array<std::vector<float>, kSixWayFaces> faces;  // straight lighting in [0, 1], per pixel
  std::vector<float> alpha;                            // opacity in [0, 1]
  std::vector<float> emissive;                         // in [0, 1]; smoke: 0

  SixWayValues faces_at(size_t pixel) const;
};

struct SixWayTextures {
  int width = 0, height = 0;
  std::vector<uint8_t> a, b;  // RGBA8 each
};

// A frame of `width` x `height` with every plane zero.
SixWayFrame blank_six_way_frame(int width, int height);

// From renders over black of a medium of white albedo, premultiplied by their coverage: the six
// faces' (in SixWayFace order) and one under ambient light 1 alone, whose value is the opacity.
// Per pixel the mean of the RGB channels; a face is its render divided by the opacity (0 where
// the opacity is 0), clamped to [0, 1].
SixWayFrame six_way_frame_from_renders(const std::array<RgbImage, kSixWayFaces>& faces,
                                       const RgbImage& opacity);

// Each plane rounded to 8 bits (round(255 v), v clamped to [0, 1]) into its channel.
SixWayTextures pack_six_way(const SixWayFrame& frame);
// The planes back from the channels (v = byte / 255).
SixWayFrame unpack_six_way(const SixWayTextures& textures);

// The frame relit by a light towards `towards_light` (camera-facing frame) of colour
// `light_color`, over black: per pixel light_color * six_way_relight(faces, w) * alpha, plus the
// emissive value times alpha in every channel.
RgbImage relight_six_way(const SixWayFrame& frame, const glm::vec3& towards_light,
                         const glm::vec3& light_color = glm::vec3(1.0f));

// The linear-light mix of two frames, weight w on `a`: the premultiplied faces and the emissive
// value mix as the renders would (w f_a alpha_a + (1 - w) f_b alpha_b), the opacity as
// w alpha_a + (1 - w) alpha_b, and the mix is stored straight again. Same sizes.
SixWayFrame cross_fade_six_way(const SixWayFrame& a, const SixWayFrame& b, float w);

}  // namespace pyro
