#include "engine/core/same_file.h"

#include <sys/stat.h>

#include <filesystem>

#include "engine/core/user_error.h"

namespace pyro {

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

void refuse_output_over_inputs(const std::string& output, const std::string& option,
                               const std::vector<NamedPath>& inputs) {
  for (const NamedPath& input : inputs)
    if (same_file(output, input.path))
      throw UserError(output, option,
                      "an output path that is none of the command's inputs; it is " + input.what +
                          " (\"" + input.path + "\"), which the output would replace");
}

void refuse_output_inside(const std::string& output, const std::string& option,
                          const std::string& folder, const std::string& owner) {
  std::string parent = std::filesystem::path(output).parent_path().string();
  if (parent.empty()) parent = ".";
  if (same_file(parent, folder))
    throw UserError(output, option, "an output path outside \"" + folder + "\", which holds " +
                                        owner + "; the file would be taken for one of them");
}

}  // namespace pyro
