#include "engine/io/isolated_call.h"

#include <poll.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <chrono>
#include <cstring>
#include <fstream>
#include <new>
#include <thread>
#include <vector>

#include "engine/core/printable_text.h"
#include "engine/core/user_error.h"
#include "engine/io/io_error.h"

// Present only when a sanitizer runtime is linked (the asan-ubsan preset, the fuzz build): the
// child clears the death callback that libFuzzer registers, so a report in the child is the
// child's failure alone and not taken for a crash of the fuzzed process.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace pyro {

namespace {

// A file descriptor closed on destruction.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// The whole of a file descriptor's file, mapped read-only.
class MappedFile {
 public:
  explicit MappedFile(int fd) {
    struct stat st;
    if (::fstat(fd, &st) != 0 || st.st_size <= 0) return;
    size_ = static_cast<size_t>(st.st_size);
    void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
    if (p == MAP_FAILED) throw std::runtime_error(std::string("mmap failed: ") + std::strerror(errno));
    data_ = static_cast<const char*>(p);
  }
  ~MappedFile() {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  std::string_view view() const { return data_ ? std::string_view(data_, size_) : std::string_view(); }

 private:
  const char* data_ = nullptr;
  size_t size_ = 0;
};

int anonymous_file(const char* name) {
  const int fd = ::memfd_create(name, MFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error(std::string("memfd_create failed: ") + std::strerror(errno));
  return fd;
}

bool write_all(int fd, const char* data, size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}

std::string read_all(int fd) {
  std::string out;
  if (::lseek(fd, 0, SEEK_SET) < 0) return out;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t r = ::read(fd, buffer, sizeof buffer);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    out.append(buffer, static_cast<size_t>(r));
  }
  return out;
}

// Length-prefixed strings in the result file: tag byte, then fields.
void put_string(std::string& out, const std::string& s) {
  const uint64_t n = s.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out += s;
}
bool get_string(std::string_view in, size_t& pos, std::string& s) {
  uint64_t n = 0;
  if (in.size() - pos < sizeof n) return false;
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  if (in.size() - pos < n) return false;
  s.assign(in.data() + pos, n);
  pos += n;
  return true;
}

uint64_t current_address_space() {
  std::ifstream statm("/proc/self/statm");
  uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

uint64_t default_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return uint64_t{8} << 30;
  return static_cast<uint64_t>(pages) * static_cast<uint64_t>(page) / 2;
}

// The last line or two of what the child wrote on stderr, for the error message.
std::string tail_of(const std::string& text) {
  std::string t = text;
  while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
  if (t.empty()) return "";
  const size_t keep = 300;
  if (t.size() > keep) t = "…" + t.substr(t.size() - keep);
  return " (its last words: " + t + ")";
}

[[noreturn]] void child_main(int result_fd, int stderr_fd, const std::function<void(ResultWriter&)>& work,
                             uint64_t memory_bytes) {
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
  for (int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) {
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_DFL;
    ::sigaction(sig, &sa, nullptr);
  }
  ::dup2(stderr_fd, STDERR_FILENO);
  // The third-party library's own messages (OpenVDB logs warnings to stdout) are captured with
  // its stderr: the program's stdout keeps only what the program prints (one JSON object).
  ::dup2(stderr_fd, STDOUT_FILENO);
  struct rlimit cap;
  cap.rlim_cur = cap.rlim_max = current_address_space() + memory_bytes;
  ::setrlimit(RLIMIT_AS, &cap);

  std::string out;
  try {
    {
      ResultWriter writer(result_fd);
      writer.append("R", 1);
      work(writer);
    }  // unmapped; the file keeps its size
    ::_exit(0);
  } catch (const UserError& e) {
    out.push_back('U');
    put_string(out, e.file());
    put_string(out, e.place());
    put_string(out, e.expected());
  } catch (const IoError& e) {
    out.push_back('I');
    put_string(out, e.file());
    put_string(out, e.action());
    put_string(out, std::to_string(e.os_error()));
  } catch (const std::bad_alloc&) {
    out.assign("A");
  } catch (const std::exception& e) {
    out.assign("E");
    put_string(out, e.what());
  } catch (...) {
    out.assign("E");
    put_string(out, "an exception of unknown type");
  }
  // An error record replaces whatever part of a result was written.
  if (::ftruncate(result_fd, 0) != 0 || ::lseek(result_fd, 0, SEEK_SET) != 0) ::_exit(1);
  const bool written = write_all(result_fd, out.data(), out.size());
  ::_exit(written ? 0 : 1);
}

}  // namespace

ResultWriter::ResultWriter(int fd) : fd_(fd) {}

ResultWriter::~ResultWriter() {
  if (map_) ::munmap(map_, capacity_);
  if (::ftruncate(fd_, static_cast<off_t>(size_)) != 0) {
    // Leaves the larger size; the parent then reads trailing zeros, which decoding refuses.
  }
}

char* ResultWriter::extend(size_t n) {
  if (size_ + n > capacity_) {
    const size_t page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
    size_t want = std::max(size_ + n, capacity_ * 2);
    want = std::max<size_t>((want + page - 1) / page * page, page);
    if (::ftruncate(fd_, static_cast<off_t>(want)) != 0) throw std::bad_alloc();
    void* p = map_ ? ::mremap(map_, capacity_, want, MREMAP_MAYMOVE)
                   : ::mmap(nullptr, want, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    map_ = static_cast<char*>(p);
    capacity_ = want;
  }
  char* at = map_ + size_;
  size_ += n;
  return at;
}

void ResultWriter::append(const void* data, size_t n) {
  if (n > 0) std::memcpy(extend(n), data, n);
}

void ResultWriter::clear() { size_ = 0; }

IsolationLimits& vdb_isolation_limits() {
  static IsolationLimits limits;
  return limits;
}

namespace {

// The error a child recorded instead of a result (child_main), thrown in the parent.
[[noreturn]] void throw_child_error(std::string_view bytes, const std::string& file, const std::string& what,
                                    const std::string& memory_note) {
  size_t pos = 1;
  const char tag = bytes[0];
  if (tag == 'U') {
    std::string f, place, expected;
    if (!get_string(bytes, pos, f) || !get_string(bytes, pos, place) ||
        !get_string(bytes, pos, expected))
      throw std::runtime_error("run_isolated: short error");
    throw UserError(f.empty() ? file : f, place, expected);
  }
  if (tag == 'I') {  // the file system refused a write: not the user's mistake (exit status 1)
    std::string f, action, os_error;
    if (!get_string(bytes, pos, f) || !get_string(bytes, pos, action) || !get_string(bytes, pos, os_error))
      throw std::runtime_error("run_isolated: short error");
    throw IoError(f, action, std::atoi(os_error.c_str()));
  }
  if (tag == 'A')
    throw UserError(file, "", what + ": it asks for more memory than allowed" + memory_note +
                                  " (damaged file, or a grid too large for this machine)");
  std::string message;
  get_string(bytes, pos, message);
  throw UserError(file, "", what + ": " + message);
}

}  // namespace

void run_isolated(const std::string& file, const std::string& what,
                  const std::function<void(ResultWriter&)>& work,
                  const std::function<void(std::string_view)>& take, const IsolationLimits& limits,
                  IsolatedRunStats* stats) {
  const Fd result(anonymous_file("pyro-isolated-result"));
  const Fd errors(anonymous_file("pyro-isolated-stderr"));
  const uint64_t memory = limits.memory_bytes ? limits.memory_bytes : default_memory_bytes();
  std::fflush(nullptr);  // nothing buffered in the parent is written twice by the child
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) child_main(result.get(), errors.get(), work, memory);

  // Wait with a deadline: poll(2) on a pidfd wakes as soon as the child ends.
  const auto start = std::chrono::steady_clock::now();
  const Fd child(static_cast<int>(::syscall(SYS_pidfd_open, pid, 0)));
  int status = 0;
  struct rusage usage = {};
  for (;;) {
    const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    if (done < 0 && errno != EINTR)
      throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
    const double left =
        limits.timeout_seconds -
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (left <= 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      throw UserError(file, "", what + " did not finish within " +
                                    std::to_string(static_cast<int>(limits.timeout_seconds)) +
                                    " s (damaged file?); gave up");
    }
    const int wait_ms = static_cast<int>(std::min(left * 1000.0 + 1.0, 1000.0));
    if (child.get() >= 0) {
      struct pollfd p = {child.get(), POLLIN, 0};
      ::poll(&p, 1, wait_ms);
    } else {
      // No pidfd (a kernel older than 5.3): nap briefly.
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  if (stats) stats->peak_rss_bytes = uint64_t(usage.ru_maxrss) * 1024;  // Linux: kilobytes
  const std::string err = read_all(errors.get());
  const std::string memory_note =
      " (the reader may use " + std::to_string(memory >> 20) + " MiB more address space)";
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    throw UserError(file, "", what + " stopped on signal " + std::to_string(sig) + " (" +
                                  strsignal(sig) + "): the file is damaged or written in a way "
                                  "this reader cannot follow" + tail_of(err));
  }
  const MappedFile mapped(result.get());
  const std::string_view bytes = mapped.view();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
    throw UserError(file, "", what + " failed (exit status " +
                                  std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                                  "): the file is damaged, or asks for more memory than allowed" +
                                  memory_note + tail_of(err));
  if (bytes[0] == 'R') {
    // The reader's own warnings (OpenVDB's log), each line escaped and prefixed.
    const std::string said = printable_lines(err, "pyro: " + printable(file) + ": OpenVDB: ");
    if (!said.empty()) std::fputs(said.c_str(), stderr);
    take(bytes.substr(1));
    return;
  }
  throw_child_error(bytes, file, what, memory_note);
}

}  // namespace pyro
