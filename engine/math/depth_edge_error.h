#pragma once
// Image error where reduced-resolution layers go wrong: near the depth discontinuities of the
// full-resolution scene (Umenhoffer et al. 2006, section 4: a layer texel holds the particles
// clipped against one scene depth, so upsampling it across a silhouette carries the particles
// behind an object onto it). The images are linear RGBA floats and the depth is view depth, top
// row first, one value per pixel, as FrameImage and RenderTarget::read_depth give them.
//
// A depth edge is found in u = 1/z, which is affine in screen coordinates on any plane (the
// reason depth buffers interpolate it), so a receding floor has no second difference at all and
// a silhouette is a jump: pixel p is an edge pixel when |u(p - e) + u(p + e) - 2 u(p)| >
// tolerance * u(p) along x or y (e one pixel). The sign says the side: at a step the last pixel
// of the nearer surface is a peak of u (second difference below 0, the near side), the first
// pixel of the farther one a trough (above 0, the far side).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pyro {

struct DepthEdges {
  int width = 0, height = 0;
  std::vector<uint8_t> near_side, far_side;  // per pixel, 1 where it borders an edge on that side
};

// Throws std::invalid_argument when view_depth does not hold width * height positive values.
DepthEdges find_depth_edges(int width, int height, std::span<const float> view_depth,
                            float tolerance);

// Chessboard (Chebyshev) distance in pixels from every pixel to the nearest pixel set in `mask`
// (two-pass transform, exact for this metric); a large value where the mask is empty.
std::vector<int> chessboard_distance(int width, int height, std::span<const uint8_t> mask);

struct DepthEdgeErrorOptions {
  float tolerance = 0.05f;  // relative second difference of 1/z that makes an edge
  int edge_radius = 4;      // edge RMSE: pixels at most this far from an edge pixel
  int halo_bound = 2;       // halo: near-side pixels farther than this from the far side,
  int halo_reach = 16;      // and at most this far from particle light on a far side
};

struct DepthEdgeInputs {
  int width = 0, height = 0;
  std::span<const float> view_depth;  // the full-resolution opaque scene's, width * height
  std::span<const float> scene;       // the opaque scene alone, RGBA
  std::span<const float> reference;   // composed with full-resolution layers, RGBA
  std::span<const float> measured;    // the image under test, RGBA
  // Optional, width * height: the farthest view depth a particle around each pixel reaches (a
  // bound). A pixel whose surface lies beyond it hides no particle, and carries no halo.
  std::span<const float> particle_far;
};

struct DepthEdgeError {
  // RMSE over RGB (values clamped to [0, 1], as engine/math/image_error.h) of measured against
  // reference, over the pixels within edge_radius of an edge pixel of either side.
  double edge_rmse = 0.0;
  size_t edge_pixels = 0;
  // Particle light carried across an opaque edge: on the pixels of a near side (nearer a
  // near-side edge pixel than a far-side one) farther than halo_bound from the far side, where
  // the reference shows the scene alone (the same 8-bit sRGB value in every channel: a GPU's
  // decoding of an sRGB texture may be a fraction of a step off the exact curve) while within
  // halo_reach it shows particle light on a far side, at most halo_bound from its edge, nearer
  // than any particle light on a near side, and particles may lie behind the pixel's surface
  // (particle_far; where given), the largest |measured - reference| over RGB (clamped), and its
  // RMS over those pixels and channels. A particle's own outline blurred by upsampling is no
  // halo: away from such an edge, or on the near surface nearer its own light than the far
  // side's (particles in front of the near surface, whose blur the upsampling spreads over it).
  double halo = 0.0;
  double halo_rms = 0.0;
  size_t halo_pixels = 0;
};

// Throws std::invalid_argument when the images and the depth do not match width x height.
DepthEdgeError depth_edge_error(const DepthEdgeInputs& in,
                                const DepthEdgeErrorOptions& options = {});

}  // namespace pyro
