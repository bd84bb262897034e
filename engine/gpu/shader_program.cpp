#include "engine/gpu/shader_program.h"

#include <algorithm>
#include <sstream>

#include "engine/core/content_path.h"
#include "engine/gpu/gpu_error.h"

namespace pyro::gpu {

namespace {

const char* stage_name(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_COMPUTE_SHADER: return "compute";
    case GL_GEOMETRY_SHADER: return "geometry";
    default: return "shader";
  }
}

}  // namespace

std::string expand_includes(const std::string& source, const std::string& file, int depth) {
  std::istringstream in(source);
  std::string line, out;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 8, "#include") != 0) {
      out += line + "\n";
      continue;
    }
    const std::string where = file + ":" + std::to_string(number) + ": ";
    const size_t open = line.find('"', start + 8);
    const size_t close = open == std::string::npos ? open : line.find('"', open + 1);
    if (close == std::string::npos || close == open + 1)
      throw GpuError(where + "expected #include \"file\" (a file under content/shaders)");
    if (depth >= 4) throw GpuError(where + "includes nested deeper than 4");
    const std::string name = line.substr(open + 1, close - open - 1);
    const std::string path = content_path("shaders/" + name);
    std::string text;
    try {
      text = read_text_file(path);
    } catch (const std::exception& e) {
      throw GpuError(where + "cannot include " + name + ": " + e.what());
    }
    out += "#line 1\n" + expand_includes(text, path, depth + 1);
    if (!out.empty() && out.back() != '\n') out += "\n";
    out += "#line " + std::to_string(number + 1) + "\n";
  }
  return out;
}

ShaderStageSource load_shader_stage(GLenum stage, const std::string& relative) {
  const std::string path = content_path(relative);
  return ShaderStageSource{stage, path, expand_includes(read_text_file(path), path)};
}

Program link_program(const std::vector<ShaderStageSource>& stages) {
  std::vector<Shader> shaders;
  std::string files;
  for (const ShaderStageSource& s : stages) {
    Shader shader(glCreateShader(s.stage));
    const char* text = s.source.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = 0;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint length = 0;
      glGetShaderiv(shader.get(), GL_INFO_LOG_LENGTH, &length);
      std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
      glGetShaderInfoLog(shader.get(), static_cast<GLsizei>(log.size()), nullptr, log.data());
      throw GpuError(s.file + ": " + stage_name(s.stage) + " shader does not compile:\n" + log);
    }
    files += (files.empty() ? "" : " + ") + s.file;
    shaders.push_back(std::move(shader));
  }
  Program program(glCreateProgram());
  for (const Shader& s : shaders) glAttachShader(program.get(), s.get());
  glLinkProgram(program.get());
  GLint ok = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program.get(), GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program.get(), static_cast<GLsizei>(log.size()), nullptr, log.data());
    throw GpuError(files + ": program does not link:\n" + log);
  }
  for (const Shader& s : shaders) glDetachShader(program.get(), s.get());
  return program;
}

std::string with_defines(const std::string& source, const std::vector<std::string>& defines) {
  if (defines.empty()) return source;
  const size_t version = source.find("#version");
  if (version == std::string::npos) throw GpuError("shader source has no #version line");
  size_t end = source.find('\n', version);
  if (end == std::string::npos) end = source.size();
  std::string lines;
  for (const std::string& d : defines) lines += "#define " + d + "\n";
  // The line after #version is line (number of lines up to it) + 1.
  const size_t version_line = static_cast<size_t>(std::count(source.begin(), source.begin() + end, '\n')) + 1;
  lines += "#line " + std::to_string(version_line + 1) + "\n";
  return source.substr(0, end + 1) + lines + source.substr(std::min(end + 1, source.size()));
}

Program load_program(const std::string& vertex_file, const std::string& fragment_file,
                     const std::vector<std::string>& defines) {
  ShaderStageSource vs = load_shader_stage(GL_VERTEX_SHADER, "shaders/" + vertex_file);
  ShaderStageSource fs = load_shader_stage(GL_FRAGMENT_SHADER, "shaders/" + fragment_file);
  vs.source = with_defines(vs.source, defines);
  fs.source = with_defines(fs.source, defines);
  return link_program({vs, fs});
}

Program load_compute_program(const std::string& compute_file,
                             const std::vector<std::string>& defines) {
  ShaderStageSource cs = load_shader_stage(GL_COMPUTE_SHADER, "shaders/" + compute_file);
  cs.source = with_defines(cs.source, defines);
  return link_program({cs});
}

GLint uniform_location(const Program& program, const char* name) {
  return glGetUniformLocation(program.get(), name);
}

}  // namespace pyro::gpu
