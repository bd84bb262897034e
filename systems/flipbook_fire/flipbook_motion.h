#pragma once
// Motion vectors of a flipbook: per pixel of a frame, how far the medium under it moves over one
// frame of the flipbook, in frame UV units (the frame's width and height are 1), u to the right
// and v down the image (rows top to bottom, as FlipbookFrames store them).
//
// On disk (motion.png, an atlas laid out like the colour atlas) they are packed the way Unity's
// VFX Graph "Flipbook Motion Blend" UV mode (docs.unity3d.com, Packages
// com.unity.visualeffectgraph, Block-FlipbookPlayer and the output contexts' UV Mode) and
// Unreal's FlipBook motion-vector material function decode them (realtimevfx.com, "UE4's Flip
// Book Motion Vector Material Function": still pixels are (128, 128, 0), the texture is biased
// and scaled to [-1, 1] and multiplied by a strength; the blend itself: Klemen Lozar, "Frame
// Blending with Motion Vectors"), as signed vectors centred on 0.5 in two linear 8-bit channels:
//   R = 0.5 + u 0.5 / strength,  G = 0.5 + v_up 0.5 / strength,  B = 0,  A = 1,
// clamped to [0, 1], decoded as (2 c - 1) strength. v_up = -v: G grows upward, as UV's v does in
// Unity (its UV origin is the bottom left: Shader Graph Flipbook node); for Unreal, whose texture
// v runs down, flip G (1 - G) or negate the decoded v. `strength` is stored in the sidecar.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pyro {

struct MotionField {
  int width = 0, height = 0;
  std::vector<float> uv;  // (u, v) per pixel, v down; 2 width height floats
  float u(int x, int y) const { return uv[(static_cast<size_t>(y) * width + x) * 2]; }
  float v(int x, int y) const { return uv[(static_cast<size_t>(y) * width + x) * 2 + 1]; }
};

// The encoding's scale for these fields: the largest |u| or |v| of any pixel, so that nothing
// clamps, raised by half a quantization step's worth (1 + 1/127) and to at least 1e-4 (a still
// medium).
float motion_strength(const std::vector<MotionField>& fields);

// RGBA8 as above (linear bytes, not sRGB), width height 4 bytes, top row first.
std::vector<uint8_t> encode_motion(const MotionField& field, float strength);
MotionField decode_motion(const std::vector<uint8_t>& rgba, int width, int height, float strength);

}  // namespace pyro
