// make_sample_volume [--seed N] [--width N] [--voxel-size S] [--half] [--fire [--kelvin]] --out FILE.vdb
// make_sample_volume --fire-box KELVIN --out FILE.vdb
// Writes the project's own procedural cloud (engine/volume/procedural_cloud.h) as an OpenVDB float
// fog volume named "density" through engine/io's writer, so this file never sees OpenVDB's
// headers. With --fire it writes the project's fire instead (engine/volume/procedural_fire.h): a
// Mantaflow-like cache frame with "density" and "temperature" (normalised heat, or kelvin with
// --kelvin); --width is then the plume's width in voxels (default 20). The committed content/volumes/sample_cloud.vdb is this tool's output with the defaults
// (`cmake --build build --target regenerate_sample_volume`); a test checks that they agree.
// --fire-box writes the fire renderers' calibration cube instead (engine/volume/procedural_fire.h,
// make_uniform_fire_box): density 1 at one temperature in kelvin.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "engine/volume/procedural_cloud.h"
#include "engine/volume/procedural_fire.h"

namespace {

int usage(const char* why) {
  std::fprintf(stderr,
               "make_sample_volume: %s\n"
               "usage: make_sample_volume [--seed N] [--width N] [--voxel-size S] [--half] [--fire [--kelvin]] "
               "--out FILE.vdb\n"
               "       make_sample_volume --fire-box KELVIN --out FILE.vdb\n",
               why);
  return 2;
}

// The fire: density and temperature (no velocity: the committed sample stays small).
int write_fire(const std::string& out, const pyro::ProceduralCloudOptions& cloud, bool width_given, bool kelvin,
               bool half) {
  pyro::ProceduralFireOptions o;
  o.seed = cloud.seed;
  if (width_given) o.width = cloud.width;
  o.voxel_size = cloud.voxel_size;
  o.kelvin = kelvin;
  o.velocity = false;
  std::vector<pyro::VdbGridToWrite> grids = pyro::make_procedural_fire(o);
  unsigned long long active = 0;
  for (pyro::VdbGridToWrite& g : grids) {
    g.half_float = half;
    if (g.name == "density")
      for (float v : g.values) active += v != 0.0f;
  }
  pyro::write_vdb_grids(out, grids);
  std::printf("{\"out\": \"%s\", \"seed\": %llu, \"dims\": [%d, %d, %d], \"active_voxels\": %llu}\n", out.c_str(),
              static_cast<unsigned long long>(o.seed), grids[0].dims[0], grids[0].dims[1], grids[0].dims[2], active);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  pyro::ProceduralCloudOptions opt;
  std::string out;
  bool half = false, fire = false, kelvin = false, width_given = false;
  double box_kelvin = 0.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    char* end = nullptr;
    if (a == "--out" && has_value) {
      out = argv[++i];
    } else if (a == "--seed" && has_value) {
      opt.seed = std::strtoull(argv[++i], &end, 10);
      if (*end != '\0') return usage("--seed expects a non-negative integer");
    } else if (a == "--width" && has_value) {
      opt.width = int(std::strtol(argv[++i], &end, 10));
      width_given = true;
      if (*end != '\0' || opt.width < 8 || opt.width > 1024) return usage("--width expects an integer in [8, 1024]");
    } else if (a == "--voxel-size" && has_value) {
      opt.voxel_size = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(opt.voxel_size > 0.0 && opt.voxel_size < 1e6))
        return usage("--voxel-size expects a number in (0, 1e6)");
    } else if (a == "--half") {
      half = true;
    } else if (a == "--fire") {
      fire = true;
    } else if (a == "--kelvin") {
      kelvin = true;
    } else if (a == "--fire-box" && has_value) {
      box_kelvin = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(box_kelvin > 10.0 && box_kelvin <= 1e6))
        return usage("--fire-box expects a temperature in kelvin in (10, 1e6]");
    } else {
      return usage(("unexpected argument \"" + a + "\"").c_str());
    }
  }
  if (out.empty()) return usage("--out FILE.vdb is required");
  if (kelvin && !fire) return usage("--kelvin applies to --fire");
  if (box_kelvin > 0.0 && (fire || half)) return usage("--fire-box takes no --fire or --half");
  try {
    // The one gate (engine/io/output_gate.h): --out is a regular file or absent, in a folder that
    // exists and takes writes; never a device, a FIFO or a folder.
    pyro::OutputGate().writes_file(out, "--out").check();
    if (box_kelvin > 0.0) {
      pyro::write_vdb_grids(out, pyro::make_uniform_fire_box(box_kelvin));
      std::printf("{\"out\": \"%s\", \"kelvin\": %g}\n", out.c_str(), box_kelvin);
      return 0;
    }
    if (fire) return write_fire(out, opt, width_given, kelvin, half);
    const pyro::DenseGrid g = pyro::make_procedural_cloud(opt);
    const glm::dvec4 t = g.index_to_world[3];
    pyro::write_vdb_fog_volume(out, g.name, g.origin, g.dims, g.values, opt.voxel_size, {t.x, t.y, t.z},
                               half);
    std::printf("{\"out\": \"%s\", \"seed\": %llu, \"dims\": [%d, %d, %d], \"active_voxels\": %llu}\n",
                out.c_str(), static_cast<unsigned long long>(opt.seed), g.dims[0], g.dims[1], g.dims[2],
                static_cast<unsigned long long>(g.active_voxels));
  } catch (const pyro::UserError& e) {
    std::fprintf(stderr, "make_sample_volume: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_sample_volume: %s\n", e.what());
    return 1;
  }
  return 0;
}
