#pragma once
// Runs a piece of work in a child process, so that a third-party reader fed a damaged file can
// neither crash, hang nor exhaust the memory of the engine.
//
// Why: OpenVDB trusts the sizes and values inside a grid's data. Fuzzing (tools/fuzz.sh vdb)
// found 10 KB files that make it allocate and touch 17 GB, read bytes other than 0/1 into a
// bool, and stop on signals; no check we can make before it reads catches all of that without
// re-implementing its decoder. The child process is the boundary instead: it is forked, its
// address space is capped (setrlimit RLIMIT_AS), it has a deadline, its stderr and stdout are
// captured, and it hands back either a result (bytes) or the UserError it threw. Anything else — a
// signal, a sanitizer report, an allocation over the cap, the deadline — becomes a UserError
// naming the file, so the engine refuses the file (exit 2) and goes on.
//
// The parent never runs the work itself. Libraries used only inside the child (OpenVDB and its
// TBB thread pool) are therefore never started in the parent, which is what makes fork safe to
// use here: a forked child of a process whose TBB pool is running would inherit a pool without
// threads.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace pyro {

struct IsolationLimits {
  double timeout_seconds = 600.0;  // the child is killed after this long
  uint64_t memory_bytes = 0;       // address space the child may add; 0: half the physical memory
};

// The limits used by the VDB reader; the fuzz targets shorten the deadline.
IsolationLimits& vdb_isolation_limits();

// Where the child writes its result: a memory-mapped anonymous file shared with the parent, so
// a large result (a dense grid) is written in place once and read by the parent in place.
class ResultWriter {
 public:
  explicit ResultWriter(int fd);
  ~ResultWriter();
  ResultWriter(const ResultWriter&) = delete;
  ResultWriter& operator=(const ResultWriter&) = delete;
  // Appends n bytes and returns where they are, to be filled; valid until the next call.
  char* extend(size_t n);
  void append(const void* data, size_t n);
  void clear();  // back to nothing (an error record replaces a partial result)
  size_t size() const { return size_; }

 private:
  int fd_;
  char* map_ = nullptr;
  size_t size_ = 0, capacity_ = 0;
};

// What a run's child used: its peak resident memory (wait4's ru_maxrss).
struct IsolatedRunStats {
  uint64_t peak_rss_bytes = 0;
};

// Forks; the child runs `work`, and `take` receives the bytes it wrote (mapped, valid during the
// call), or the UserError the child threw is rethrown. `file` and `what` ("reading the OpenVDB
// file", ...) name the work in errors. Other exceptions in the child become
// UserError(file, "", what + ": " + e.what()).
void run_isolated(const std::string& file, const std::string& what,
                  const std::function<void(ResultWriter&)>& work,
                  const std::function<void(std::string_view)>& take, const IsolationLimits& limits,
                  IsolatedRunStats* stats = nullptr);

}  // namespace pyro
