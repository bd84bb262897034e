// Progress reports without printing: a task tells its sink begin, each update with the stage
// named last, and finish exactly once (also when it ends early); a null sink takes nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/progress_sink.h"

namespace pyro {
namespace {

class RecordingSink : public ProgressSink {
 public:
  void begin(const std::string& label, size_t total) override {
    log.push_back("begin " + label + " " + std::to_string(total));
  }
  void update(size_t done, const std::string& stage) override {
    log.push_back(std::to_string(done) + (stage.empty() ? "" : " " + stage));
  }
  void finish() override { log.push_back("finish"); }
  std::vector<std::string> log;
};

TEST(ProgressTask, ReportsToItsSinkInOrderAndFinishesOnce) {
  RecordingSink sink;
  {
    ProgressTask task(&sink, "bench", 3);
    task.update(1);
    task.stage(1, "error");
    task.update(2);  // keeps the stage named last
    task.finish();
    task.update(3);  // after finish: nothing
  }
  EXPECT_EQ(sink.log, (std::vector<std::string>{"begin bench 3", "1", "1 error", "2 error", "finish"}));
}

TEST(ProgressTask, FinishesWhenItEndsAndANullSinkTakesNothing) {
  RecordingSink sink;
  { ProgressTask task(&sink, "soak", 10); }
  EXPECT_EQ(sink.log, (std::vector<std::string>{"begin soak 10", "finish"}));
  ProgressTask none(nullptr, "nothing", 5);
  none.update(1);
  none.finish();
}

}  // namespace
}  // namespace pyro
