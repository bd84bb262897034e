// Stability: NaN and infinity in the inputs are stopped at the boundary. A scene file's number
// too large for a double (JSON has no NaN or Infinity literals; 1e400 is how an infinity
// arrives) and a particle file holding NaN or infinity are refused with exit status 2, a message
// naming the file and the place, and nothing written. The naive path - taking the values in -
// poisons the image: a NaN colour reaches every pixel the particle covers, even in the CPU ground
// truth.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/reference/particle_reference.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// A particle file in the documented layout (docs/particle_format.md), written byte by byte
// without write_particle_file's check.
void write_raw_particle_file(const fs::path& p, const std::vector<GaussianParticle>& particles) {
  std::ofstream out(p, std::ios::binary);
  const uint32_t version = 1, record = sizeof(GaussianParticle), meta = 2;
  const uint64_t count = particles.size();
  out.write("PYROPTCL", 8);
  out.write(reinterpret_cast<const char*>(&version), 4);
  out.write(reinterpret_cast<const char*>(&record), 4);
  out.write(reinterpret_cast<const char*>(&count), 8);
  out.write(reinterpret_cast<const char*>(&meta), 4);
  out.write("{}", 2);
  out.write(reinterpret_cast<const char*>(particles.data()),
            static_cast<std::streamsize>(count * sizeof(GaussianParticle)));
}

TEST(StabilityNonFiniteInput, NaiveNaNColourPoisonsTheGroundTruthImage) {
  ParticlePool pool(1);
  ParticleInit p;
  p.density = 0.5f;
  p.color = {std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f};
  pool.spawn(p);
  const CameraFrame cam = make_camera_frame({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30.0f, 0.1f, 100.0f, 9, 9);
  const RgbImage img = render_particles_reference(pool, cam, glm::dvec3(0.2), 1);
  EXPECT_TRUE(std::isnan(img.at(4, 4)[0]));
}

TEST(StabilityNonFiniteInput, InfiniteNumberInASceneIsRefusedNamingThePlace) {
  const fs::path dir = test::scratch_dir("stability_inf_scene");
  write(dir / "inf.json", "{\n  \"clouds\": [{\"count\": 10, \"radius\": 1e400}]\n}\n");
  const test::CommandResult r =
      test::run_pyro({"render", (dir / "inf.json").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("inf.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 2, column"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(StabilityNonFiniteInput, NaNOrInfinityInAParticleFileIsRefusedNamingTheParticle) {
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    const fs::path dir = test::scratch_dir(std::isnan(bad) ? "stability_nan_pyrop" : "stability_inf_pyrop");
    ParticleFile f;
    f.particles.resize(3);
    for (GaussianParticle& p : f.particles) p.density = 0.5f;
    f.particles[1].y = bad;
    EXPECT_THROW(write_particle_file((dir / "bad.pyrop").string(), f), UserError)
        << "the writer refuses what the reader would";
    EXPECT_FALSE(fs::exists(dir / "bad.pyrop"));
    write_raw_particle_file(dir / "bad.pyrop", f.particles);  // as a damaged or foreign file
    write(dir / "scene.json", R"({"volumes": [{"file": "bad.pyrop"}]})");
    const test::CommandResult r =
        test::run_pyro({"render", (dir / "scene.json").string(), "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("bad.pyrop"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("particle 1"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("finite"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
}

}  // namespace
}  // namespace pyro
