// The farm record read back as written, and a damaged one refused with the place named.
#include "tools/farm/farm_record.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/user_error.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

FarmRecord sample_farm_record() {
  FarmRecord r;
  r.scene = "/shared/scenes/explosion.json";
  r.frames = {10, 69};
  r.chunk = 10;
  r.identity = {
      {"digest", std::string(64, 'a')}, {"parts", {{"scene", "b"}}}, {"scene_file", r.scene}};
  r.pyro = "/shared/pyro/bin/pyro";
  r.render_options = {"--width", "160", "--depth"};
  r.partition = "render";
  r.scheduler = {"1-00:00:00", "8G", 4, "proj", {"--qos=long"}};
  r.frames_per_second = 25.0;
  r.submissions.push_back({"1234", "1235", {{10, 19}, {20, 29}}});
  r.superseded = {std::string(64, 'c')};
  return r;
}

TEST(FarmRecord, ReadsBackWhatWasWritten) {
  const std::filesystem::path dir = test::scratch_dir("record");
  std::filesystem::create_directories(farm_folder(dir.string()));
  const FarmRecord r = sample_farm_record();
  write_farm_record(dir.string(), r);
  const FarmRecord back = read_farm_record(dir.string());
  EXPECT_EQ(farm_record_json(back), farm_record_json(r));
  EXPECT_EQ(back.digest(), std::string(64, 'a'));
  EXPECT_EQ(chunk_folder("/d", {20, 29}), std::filesystem::path("/d/.farm/chunks/20-29"));
}

TEST(FarmRecord, ARecordWithoutSchedulerOptionsReadsAsTheClustersDefaults) {
  nlohmann::json j = farm_record_json(sample_farm_record());
  j.erase("scheduler");
  j.erase("superseded");
  const FarmRecord r = farm_record_from_json(j, "farm.json");
  EXPECT_EQ(r.scheduler.time, "");
  EXPECT_EQ(r.scheduler.cpus_per_task, 0);
  EXPECT_TRUE(r.scheduler.sbatch_args.empty());
  EXPECT_TRUE(r.superseded.empty());
  j = farm_record_json(sample_farm_record());
  j["scheduler"]["cpus_per_task"] = "four";
  try {
    farm_record_from_json(j, "farm.json");
    FAIL() << "a CPU count that is no number was read";
  } catch (const UserError& e) {
    EXPECT_EQ(e.place(), "/scheduler/cpus_per_task");
  }
}

TEST(FarmRecord, ADamagedRecordNamesTheFileAndThePlace) {
  nlohmann::json j = farm_record_json(sample_farm_record());
  j["chunk"] = 0;
  try {
    farm_record_from_json(j, "farm.json");
    FAIL() << "a chunk of 0 frames was read";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), "farm.json");
    EXPECT_EQ(e.place(), "/chunk");
  }
  j = farm_record_json(sample_farm_record());
  j["submissions"][0]["chunks"][1] = {29, 20};
  EXPECT_THROW(farm_record_from_json(j, "farm.json"), UserError);
  j = farm_record_json(sample_farm_record());
  j.erase("pyro");
  try {
    farm_record_from_json(j, "farm.json");
    FAIL() << "a record without the binary was read";
  } catch (const UserError& e) {
    EXPECT_EQ(e.place(), "/pyro");
  }
}

}  // namespace
}  // namespace pyro
