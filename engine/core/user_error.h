#pragma once
// An error the user can cause and fix: a scene file, a VDB file or a command-line argument.
// It names the file, the place inside it (JSON pointer, grid name, argument) and what was
// expected. The command line prints what() and exits with status 2.
#include <stdexcept>
#include <string>

namespace pyro {

class UserError : public std::runtime_error {
 public:
  UserError(std::string file, std::string place, std::string expected)
      : std::runtime_error(compose(file, place, expected)),
        file_(std::move(file)),
        place_(std::move(place)),
        expected_(std::move(expected)) {}

  const std::string& file() const { return file_; }
  const std::string& place() const { return place_; }
  const std::string& expected() const { return expected_; }

 private:
  static std::string compose(const std::string& file, const std::string& place,
                             const std::string& expected) {
    // No empty fields: an argument's error has no file ("at --error: ...").
    std::string s = file;
    if (!place.empty()) s += (s.empty() ? "at " : ": at ") + place;
    s += (s.empty() ? "" : ": ") + expected;
    return s;
  }
  std::string file_, place_, expected_;
};

}  // namespace pyro
