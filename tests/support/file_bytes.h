#pragma once
// A file's bytes, for the tests that compare outputs byte for byte ("" when it cannot be read).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace pyro::test {

inline std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace pyro::test
