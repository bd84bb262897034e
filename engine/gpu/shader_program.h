#pragma once
// GLSL programs built from files under the content directory (content/shaders). Compile and
// link errors throw GpuError carrying the file name and the driver's log.
#include <string>
#include <vector>

#include "engine/gpu/gl_objects.h"

namespace pyro::gpu {

struct ShaderStageSource {
  GLenum stage;          // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
  std::string file;      // path, for messages
  std::string source;
};

// Reads `relative` (e.g. "shaders/billboard.vert") from the content directory, its includes
// expanded (expand_includes).
ShaderStageSource load_shader_stage(GLenum stage, const std::string& relative);

// `source` (read from `file`, for messages) with each line `#include "name"` replaced by the
// text of content/shaders/name (its own includes expanded, at most 4 deep), framed by #line
// directives so that compile errors after it keep the file's line numbers. A malformed or
// missing include throws GpuError naming the file and line.
std::string expand_includes(const std::string& source, const std::string& file, int depth = 0);

Program link_program(const std::vector<ShaderStageSource>& stages);

// Convenience: vertex + fragment shader files under content/shaders. `defines` ("NAME VALUE" or
// "NAME") become #define lines after each stage's #version line: shader variants. On llvmpipe a
// branch on a uniform still runs both sides (texture fetches included) under an execution mask,
// so a feature that is off must be compiled out, not skipped, to cost nothing.
Program load_program(const std::string& vertex_file, const std::string& fragment_file,
                     const std::vector<std::string>& defines = {});

// A compute program from one file under content/shaders, with `defines` as load_program's.
Program load_compute_program(const std::string& compute_file,
                             const std::vector<std::string>& defines = {});

// The source with #define lines inserted after its #version line (and a #line directive, so
// that compile errors keep the file's own line numbers).
std::string with_defines(const std::string& source, const std::vector<std::string>& defines);

GLint uniform_location(const Program& program, const char* name);

}  // namespace pyro::gpu
