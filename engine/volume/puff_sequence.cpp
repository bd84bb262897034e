#include "engine/volume/puff_sequence.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/io/vdb_reader.h"

namespace pyro {

std::vector<float> puff_frame_values(const PuffSequenceOptions& o, int k) {
  const double t = double(k) / double(std::max(o.frames - 1, 1));
  const double n = double(o.side);
  const double cx = n * (0.3 + 0.4 * t), cy = 0.5 * n, cz = 0.5 * n, r = n * (0.08 + 0.06 * t);
  std::vector<float> values(std::size_t(o.side) * std::size_t(o.side) * std::size_t(o.side), 0.0f);
  std::size_t i = 0;
  for (int z = 0; z < o.side; ++z)
    for (int y = 0; y < o.side; ++y)
      for (int x = 0; x < o.side; ++x, ++i) {
        const double d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz);
        const double v = o.peak * std::exp(-d2 / (2.0 * r * r));
        values[i] = v >= o.cutoff ? float(v) : 0.0f;
      }
  return values;
}

std::vector<std::string> write_puff_sequence(const std::string& folder, const PuffSequenceOptions& o) {
  std::vector<std::string> paths;
  for (int k = 0; k < o.frames; ++k) {
    char name[512];
    std::snprintf(name, sizeof name, o.pattern.c_str(), o.first_frame + k);
    const std::string path = (std::filesystem::path(folder) / name).string();
    write_vdb_fog_volume(path, "density", {0, 0, 0}, {o.side, o.side, o.side}, puff_frame_values(o, k),
                         1.0 / o.side, {0.0, 0.0, 0.0});
    paths.push_back(path);
  }
  return paths;
}

}  // namespace pyro
