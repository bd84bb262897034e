#pragma once
// A tmpfs mounted on a scratch folder for fault-injection tests (a full disk, a read-only file
// system, a mount point as an output folder). Mounting needs root (CI runs as root); when it is
// not permitted, mounted() is false and why() says so, for GTEST_SKIP.
#include <sys/mount.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

namespace pyro::test {

class ScratchMount {
 public:
  // `options` as for mount -o, e.g. "size=200k"; `read_only` mounts it read-only.
  ScratchMount(std::filesystem::path dir, const std::string& options, bool read_only = false)
      : dir_(std::move(dir)) {
    std::filesystem::create_directories(dir_);
    const unsigned long flags = read_only ? MS_RDONLY : 0;
    if (::mount("tmpfs", dir_.c_str(), "tmpfs", flags, options.c_str()) == 0) mounted_ = true;
    else why_ = "cannot mount a tmpfs on " + dir_.string() + " (" + std::strerror(errno) +
                "): fault-injection tests need root";
  }
  ~ScratchMount() {
    if (mounted_) ::umount2(dir_.c_str(), MNT_DETACH);
  }
  ScratchMount(const ScratchMount&) = delete;
  ScratchMount& operator=(const ScratchMount&) = delete;

  bool mounted() const { return mounted_; }
  const std::string& why() const { return why_; }
  const std::filesystem::path& dir() const { return dir_; }
  // Remounts read-only (after files were written while writable).
  bool make_read_only() {
    return ::mount("tmpfs", dir_.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, nullptr) == 0;
  }

 private:
  std::filesystem::path dir_;
  bool mounted_ = false;
  std::string why_;
};

}  // namespace pyro::test
