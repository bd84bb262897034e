#include "engine/io/text_file.h"

#include "engine/io/durable_file.h"

namespace pyro {

void write_text_file(const std::string& path, const std::string& text) {
  write_file_durably(path, text);
}

}  // namespace pyro
