#pragma once
// A private folder for a command's intermediate files: made fresh (mkdtemp) under the system's
// temporary folder with a name of `prefix` and six random characters, and removed with everything
// in it when the object goes. Never a user's folder: nothing but the engine writes there, so
// removing it takes nothing of theirs (the output gate, engine/io/output_gate.h, governs outputs).
#include <filesystem>
#include <string>

namespace pyro {

class ScratchFolder {
 public:
  // Throws UserError naming the pattern when no folder can be made.
  explicit ScratchFolder(const std::string& prefix);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path path;

 private:
  static std::filesystem::path make(const std::string& prefix);
};

}  // namespace pyro
