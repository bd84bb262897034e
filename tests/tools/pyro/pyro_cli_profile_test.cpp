// Profiling runs end to end: `pyro render --trace` (and `pyro profile --trace`) writes Chrome trace
// events with one span per system per frame nested in its frame, GPU passes on their own track
// with the explosion's three layers inside billboard_render; `pyro profile --json` has every
// system with consistent statistics and the explosion's known particle counts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

using nlohmann::json;

constexpr int kPyroCliProfileFrames = 3;

TEST(PyroCliProfile, ExplosionTraceHasASpanPerSystemPerFrame) {
  const auto dir = test::scratch_dir("profile_trace");
  const std::string trace_file = (dir / "explosion.trace.json").string();
  const auto r = test::run_pyro({"render", test::scene_path("explosion.json"), "--out",
                                 (dir / "frames").string(), "--frames", std::to_string(kPyroCliProfileFrames),
                                 "--width", "96", "--height", "96", "--trace", trace_file, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json summary = test::last_json_line(r.out);
  EXPECT_EQ(summary["trace"], trace_file);
  std::vector<std::string> systems;
  std::map<std::string, std::string> phase;
  for (const json& s : summary["systems"]) {
    systems.push_back(s["name"]);
    phase[s["name"]] = s["phase"];
  }
  ASSERT_GE(systems.size(), 10u);  // spawn .. composite of scene_runtime.h

  std::ifstream in(trace_file);
  ASSERT_TRUE(in) << trace_file;
  const json trace = json::parse(in);  // throws (fails the test) unless valid JSON
  ASSERT_TRUE(trace["traceEvents"].is_array());

  struct Span {
    double ts, dur;
  };
  std::map<int, Span> frames;                                 // CPU frame spans
  std::map<std::pair<int, std::string>, std::vector<Span>> cpu, gpu;  // (frame, name)
  std::set<int> named_tracks, used_tracks;
  for (const json& e : trace["traceEvents"]) {
    if (e["ph"] == "M") {
      if (e["name"] == "thread_name") named_tracks.insert(e["tid"].get<int>());
      continue;
    }
    ASSERT_EQ(e["ph"], "X");
    const Span s{e["ts"].get<double>(), e["dur"].get<double>()};
    const int f = e["args"]["frame"];
    const int tid = e["tid"];
    used_tracks.insert(tid);
    if (e["cat"] == "frame") {
      EXPECT_GT(s.dur, 0.0) << "a frame that renders takes time: " << e.dump();
      EXPECT_EQ(tid, 1);
      EXPECT_FALSE(frames.count(f)) << "two frame spans for frame " << f;
      frames[f] = s;
    } else if (e["cat"] == "gpu") {
      EXPECT_EQ(tid, 2) << e.dump();
      gpu[{f, e["name"]}].push_back(s);
    } else {
      // A system: on the frame's thread (1) or on a worker's track (3, 4, ...); GL systems
      // always on the frame's thread, which owns the context.
      EXPECT_TRUE(tid == 1 || tid >= 3) << e.dump();
      const std::string p = e["cat"];
      if (p == "render" || p == "composite" || p == "output") {
        EXPECT_EQ(tid, 1) << e.dump();
      }
      cpu[{f, e["name"]}].push_back(s);
    }
  }
  for (const int tid : used_tracks) EXPECT_TRUE(named_tracks.count(tid)) << "track " << tid;
  ASSERT_EQ(frames.size(), size_t(kPyroCliProfileFrames));
  for (int f = 0; f < kPyroCliProfileFrames; ++f) {
    ASSERT_TRUE(frames.count(f));
    const Span frame = frames[f];
    for (const std::string& name : systems) {
      const auto& spans = cpu[std::make_pair(f, name)];
      ASSERT_EQ(spans.size(), 1u) << name << " in frame " << f;
      EXPECT_GE(spans[0].ts, frame.ts - 1e-3) << name;
      EXPECT_LE(spans[0].ts + spans[0].dur, frame.ts + frame.dur + 1e-3) << name;
      const std::string& p = phase[name];
      if (p == "render" || p == "composite" || p == "output") {
        EXPECT_EQ(gpu[std::make_pair(f, name)].size(), 1u) << "GPU span of " << name << " in frame " << f;
      }
    }
    // The three media layers of the explosion, inside billboard_render on the GPU timeline.
    const Span outer = gpu[std::make_pair(f, std::string("billboard_render"))].at(0);
    for (const char* layer : {"dust layer", "smoke layer", "fire layer"}) {
      const auto& spans = gpu[std::make_pair(f, std::string(layer))];
      ASSERT_EQ(spans.size(), 1u) << layer << " in frame " << f;
      EXPECT_GE(spans[0].ts, outer.ts - 1e-3) << layer;
      EXPECT_LE(spans[0].ts + spans[0].dur, outer.ts + outer.dur + 1e-3) << layer;
    }
  }
}

TEST(PyroCliProfile, ProfileJsonHasEverySystemAndTheExplosionsParticles) {
  const auto r = test::run_pyro({"profile", test::scene_path("explosion.json"), "--frames", "4",
                                 "--width", "96", "--height", "96", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = test::last_json_line(r.out);
  const std::set<std::string> expected = {"cloud_emitter", "emitter", "cloud_drift", "animation",
                                          "light_animation", "lighting", "mesh_shadow", "light_block", "light_upload",
                                          "camera_orbit", "stereo_camera", "sorting", "mesh_render",
                                          "billboard_render", "composite",
                                          // scheduled in every scene, idle without fires
                                          "flipbook_orient", "flipbook_render",
                                          // and idle without a "shadows" block
                                          "shadow_map", "shadow_rays", "fire_lights",
                                          // and idle without a particle sequence
                                          "volume_sequence"};
  std::set<std::string> names;
  for (const json& s : j["systems"]) {
    names.insert(s["name"]);
    const double mean = s["mean_ms"], median = s["median_ms"], p95 = s["p95_ms"],
                 lo = s["min_ms"], hi = s["max_ms"];
    EXPECT_EQ(s["samples"], 4) << s.dump();
    // Each system's span lies inside its frame's, so its mean cannot exceed the frames' mean.
    EXPECT_LE(mean, j["frame_mean_ms"].get<double>()) << s.dump();
    EXPECT_LE(lo, median) << s.dump();
    EXPECT_LE(median, p95) << s.dump();
    EXPECT_LE(p95, hi) << s.dump();
    EXPECT_LE(lo, mean) << s.dump();
    EXPECT_LE(mean, hi) << s.dump();
  }
  EXPECT_EQ(names, expected);
  // content/scenes/explosion.json: bursts of 16 dust, 135 fire and 112 smoke, all alive.
  EXPECT_EQ(j["particles"]["live"], 263);
  std::map<std::string, int> by_source;
  for (const json& s : j["particles"]["sources"]) by_source[s["name"]] = s["live"];
  EXPECT_EQ(by_source["dust"], 16);
  EXPECT_EQ(by_source["fire"], 135);
  EXPECT_EQ(by_source["smoke"], 112);
  int media = 0;
  for (const auto& [medium, n] : j["particles"]["by_medium"].items()) media += n.get<int>();
  EXPECT_EQ(media, 263);
  // 16 float attributes, one byte of medium, a 32-bit id (engine/particles/particle_pool.h).
  EXPECT_EQ(j["memory"]["bytes_per_particle_slot"], 16 * 4 + 1 + 4);
  ASSERT_EQ(j["layers"].size(), 3u);
  for (const json& l : j["layers"]) {
    EXPECT_GT(l["fragments_mean"].get<double>(), 0.0) << l.dump();
    // A layer at scale 1/2 of 96x96 has 48x48 texels; billboards overlap, so this bounds nothing
    // from above except by the particle count.
    EXPECT_LE(l["fragments_max"].get<double>(), 263.0 * 48 * 48) << l.dump();
  }
}

TEST(PyroCliProfile, TraceIntoAMissingFolderIsRefusedBeforeRendering) {
  const auto dir = test::scratch_dir("profile_bad_trace");
  const auto out = dir / "frames";
  const auto r = test::run_pyro({"render", test::scene_path("explosion.json"), "--out",
                                 out.string(), "--frames", "1", "--width", "32", "--height", "32",
                                 "--trace", (dir / "no_such_folder" / "t.json").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--trace"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(PyroCliProfile, ProfileTraceNamesTheSameSystemsAsItsReport) {
  const auto dir = test::scratch_dir("profile_command_trace");
  const std::string trace_file = (dir / "profile.trace.json").string();
  const auto r = test::run_pyro({"profile", test::scene_path("explosion.json"), "--frames", "2",
                                 "--width", "64", "--height", "64", "--trace", trace_file, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json summary = test::last_json_line(r.out);
  EXPECT_EQ(summary["trace"], trace_file);
  std::set<std::string> reported, traced;
  for (const json& s : summary["systems"]) reported.insert(s["name"]);
  std::ifstream in(trace_file);
  ASSERT_TRUE(in) << trace_file;
  const json trace = json::parse(in);
  for (const json& e : trace["traceEvents"])
    if (e["ph"] == "X" && e["cat"] != "frame" && e["cat"] != "gpu") traced.insert(e["name"]);
  EXPECT_EQ(traced, reported);
  EXPECT_TRUE(reported.count("sorting") && reported.count("stereo_camera") &&
              reported.count("billboard_render"));

  const auto bad = test::run_pyro({"profile", test::scene_path("explosion.json"), "--frames", "1",
                                   "--trace", (dir / "no_such_folder" / "t.json").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--trace"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace pyro
