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

// Reads `relative` (e.g. "shaders/billboard.vert") from the content directory.
ShaderStageSource load_shader_stage(GLenum stage, const std::string& relative);

Program link_program(const std::vector<ShaderStageSource>& stages);

// Convenience: vertex + fragment shader files under content/shaders.
Program load_program(const std::string& vertex_file, const std::string& fragment_file);

GLint uniform_location(const Program& program, const char* name);

}  // namespace pyro::gpu
