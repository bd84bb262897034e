#pragma once
// A synthetic animated volume for tests and benchmarks: a Gaussian puff of smoke that drifts
// along +x and grows, one OpenVDB file per frame (written through engine/io/vdb_reader.h).
//
// Frame k of n (t = k / max(n - 1, 1)): density(p) = peak exp(-|p - c(t)|^2 / (2 r(t)^2)) over a
// cube of `side` voxels, set to 0 below `cutoff` (so the active voxels are a ball), with
// c(t) = side (0.3 + 0.4 t, 0.5, 0.5) and r(t) = side (0.08 + 0.06 t) in voxels. Voxel size
// 1 / side, so the cube is one world unit whatever its resolution.
#include <cstdint>
#include <string>
#include <vector>

namespace pyro {

struct PuffSequenceOptions {
  int frames = 100;
  int side = 48;          // voxels along each axis
  double peak = 1.0;
  double cutoff = 0.02;   // values below become 0 (inactive)
  int first_frame = 1;    // the number in the first file's name
  std::string pattern = "puff_%04d.vdb";  // the file names (one integer conversion)
};

// The values of frame k (0-based) over the cube, x fastest.
std::vector<float> puff_frame_values(const PuffSequenceOptions& options, int k);

// Writes every frame into `folder` (which must exist); returns the paths in frame order.
std::vector<std::string> write_puff_sequence(const std::string& folder, const PuffSequenceOptions& options);

}  // namespace pyro
