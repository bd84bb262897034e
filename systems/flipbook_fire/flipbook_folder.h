#pragma once
// A flipbook on disk: a folder of PNG frames (a user's own video frames, or one baked by
// `pyro bake-flipbook`), played in file-name order. Frames named PREFIX + digits + ".png" must
// be numbered without gaps, and every frame must have the first frame's size; anything else is
// refused with a UserError naming the folder or the file. An optional `flipbook.json` in the
// folder (written by the bake) states the frame count, which is then checked too. A folder holding
// an atlas sidecar (atlas.json, flipbook_atlas_sidecar.h) is read as an atlas instead: its tiles
// become the same frames a folder of the same frames gives, with the motion vectors when the
// bake wrote them (flipbook_atlas_folder.h). A folder holding a six-way sidecar (six_way.json,
// from `pyro bake-flipbook --six-way`) is read as six-way lightmaps (flipbook_six_way_folder.h).
#include <cstdint>
#include <string>
#include <vector>

#include "components/flipbook_fire.h"
#include "systems/flipbook_fire/flipbook_motion.h"

namespace pyro {

struct FlipbookFrames {
  std::string folder;
  int width = 0, height = 0;
  std::vector<std::string> files;             // in playing order
  std::vector<std::vector<uint8_t>> rgba;     // per frame, 8-bit sRGB RGBA, row 0 at the top
  // Per frame, the medium's motion over one frame (an atlas bake's motion.png); empty: none.
  std::vector<MotionField> motion;
  // Per frame, six-way lightmap B (left, bottom, front, emissive; Unity VFX Graph's packing,
  // systems/flipbook_fire/six_way_basis.h); empty: not a six-way flipbook. When present,
  // `rgba` holds lightmap A (right, top, back, alpha), and both hold linear values, not sRGB.
  std::vector<std::vector<uint8_t>> six_way_b;

  bool six_way() const { return !six_way_b.empty(); }
};

// One frame's RGBA from 8-bit pixels of 1 to 4 channels (below).
std::vector<uint8_t> flipbook_rgba(const uint8_t* pixels, int width, int height, int channels);

// Grey, grey + alpha and RGB frames get alpha = their brightest channel (flames filmed on
// black: black is transparent); RGBA frames keep their alpha.
FlipbookFrames read_flipbook_folder(const std::string& folder);

// The thesis' preparation steps (Rose 2007, section 4.2; components/flipbook_fire.h): crop,
// then black out the bottom `base_line` of the height and ramp linearly from black over the next
// `soften`. Row y (0 at the top) of a frame h rows high, at height above the bottom
// a = (h - y - 0.5) / h, keeps the fraction
//   0 for a < base_line;  (a - base_line) / soften for a < base_line + soften;  1 above,
// of every channel (alpha included); of a six-way flipbook, of its alpha alone (its lighting
// stays: the smoke thins out, it does not darken), both lightmaps cropped. Motion vectors are cropped with their frames and rescaled to
// the cropped frame's UV. Throws std::invalid_argument for a crop outside [0, 1] or
// empty (the scene loader checks these first).
void prepare_flipbook(FlipbookFrames& frames, const FlipbookPreparation& preparation);

// The fraction kept at height a (above): exposed for tests.
float base_softening(float a, float base_line, float soften);

}  // namespace pyro
