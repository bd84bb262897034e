// The scheduler options' forms, against sbatch(1)'s: what Slurm takes is taken, the rest is
// refused before anything is written, naming the option.
#include "tools/farm/slurm_options.h"

#include <gtest/gtest.h>

#include <string>

#include "engine/core/user_error.h"

namespace pyro {
namespace {

TEST(SlurmOptions, TimesInSlurmsForms) {
  for (const char* t : {"0", "90", "30:00", "2:30:00", "100:00:00", "1-12", "1-12:30",
                        "1-12:30:15", "UNLIMITED", "INFINITE", "unlimited"})
    EXPECT_TRUE(is_slurm_time(t)) << t;
  for (const char* t : {"", "1h", "1:75", "1:00:60", "1-24", "-3", "2-", "1-2-3", "1:2:3:4",
                        "1.5", " 90", "forever", "1-12:30:15:00"})
    EXPECT_FALSE(is_slurm_time(t)) << t;
}

TEST(SlurmOptions, MemorySizes) {
  for (const char* m : {"0", "2048", "500M", "4G", "4g", "1T", "64K"}) EXPECT_TRUE(is_slurm_memory(m)) << m;
  for (const char* m : {"", "G", "4GB", "-4G", "1.5G", "4 G", "4X"}) EXPECT_FALSE(is_slurm_memory(m)) << m;
}

// The option a refusal of `s` names; empty when `s` is taken.
std::string refused_option(const FarmScheduler& s) {
  try {
    check_farm_scheduler(s);
  } catch (const UserError& e) {
    return e.place();
  }
  return {};
}

TEST(SlurmOptions, EachRefusalNamesItsOption) {
  EXPECT_EQ(refused_option({"1-12", "4G", 8, "proj_a.b-c", {"--qos=high", "-N1"}}), "");
  EXPECT_EQ(refused_option({"1h", "", 0, "", {}}), "--time");
  EXPECT_EQ(refused_option({"", "4GB", 0, "", {}}), "--mem");
  EXPECT_EQ(refused_option({"", "", -1, "", {}}), "--cpus-per-task");
  EXPECT_EQ(refused_option({"", "", 0, "a b", {}}), "--account");
  for (const char* arg : {"qos=high", "-", "--", "--array=0-3", "-a0-3", "--dependency=after:1",
                          "--output=x", "--job-name=x", "--wrap=ls", "--time=5", "-t5",
                          "--partition=p", "--mem=1G", "-c4", "--account=x"})
    EXPECT_EQ(refused_option({"", "", 0, "", {arg}}), "--sbatch-arg") << arg;
}

}  // namespace
}  // namespace pyro
