#pragma once
// Frames over nothing (RenderSettings::transparent: scene key output.background "none", pyro
// render --background transparent). The frames are composed as the opaque ones are, over the
// scene's background colour B, with alpha a the coverage of the media and the meshes carried
// through the composite (content/shaders/compose.frag, TRANSPARENT); the sinks then take the
// background out, so that compositing a frame OVER B gives the opaque frame back:
//   EXR (linear, premultiplied, Porter & Duff 1984 "over"): opaque = P + B (1 - a), so
//       P = opaque - B (1 - a), with B as the views hold it (the scene target's clear colour,
//       read back: 8-bit sRGB for layered views, half floats otherwise), P = 0 where a = 0.
//   PNG (8-bit sRGB, straight alpha, composited in the encoded values as image viewers do):
//       opaque = C a + B_s (1 - a), so C = (opaque - B_s (1 - a)) / a. Light that no coverage
//       accounts for (fire's emission over the background, drawn with the (1 - dst, 1) blend)
//       cannot be held as a straight colour of at most 1: there a is raised to the least value
//       that holds it, C <= 1. C is rounded for the 8-bit a, so that C a + B_s (1 - a) is
//       within half a level of the opaque byte.
#include <array>
#include <optional>
#include <vector>

#include "engine/ecs/world.h"
#include "systems/output/frame_source.h"

namespace pyro {

// The background of `world`'s frames as they hold it, when its RenderSettings ask for
// transparent frames; nullopt otherwise. Main thread, GL current, a frame drawn.
std::optional<FrameBackground> held_background(ecs::World& world);

// Linear RGBA composed over `background` (FrameBackground::linear) to premultiplied RGBA over
// nothing, in place.
void remove_linear_background(std::vector<float>& rgba, const std::array<float, 3>& background);

// A shown image composed over `background` (FrameBackground::shown) to straight-alpha RGBA8
// over nothing.
ShownImage straight_alpha_image(const ShownImage& shown, const std::array<float, 3>& background);

}  // namespace pyro
