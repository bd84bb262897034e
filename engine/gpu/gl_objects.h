#pragma once
// Move-only owners of OpenGL object names. Each deletes its object when it goes away, so a
// failure part-way through building a renderer leaks nothing.
#include <epoxy/gl.h>

#include <utility>

namespace pyro::gpu {

template <void (*Delete)(GLuint)>
class GlObject {
 public:
  GlObject() = default;
  explicit GlObject(GLuint name) : name_(name) {}
  ~GlObject() { reset(); }
  GlObject(GlObject&& o) noexcept : name_(std::exchange(o.name_, 0)) {}
  GlObject& operator=(GlObject&& o) noexcept {
    if (this != &o) {
      reset();
      name_ = std::exchange(o.name_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_) Delete(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

namespace detail {
inline void delete_buffer(GLuint n) { glDeleteBuffers(1, &n); }
inline void delete_vertex_array(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void delete_texture(GLuint n) { glDeleteTextures(1, &n); }
inline void delete_framebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void delete_query(GLuint n) { glDeleteQueries(1, &n); }
inline void delete_program(GLuint n) { glDeleteProgram(n); }
inline void delete_shader(GLuint n) { glDeleteShader(n); }
}  // namespace detail

using Buffer = GlObject<detail::delete_buffer>;
using VertexArray = GlObject<detail::delete_vertex_array>;
using Texture = GlObject<detail::delete_texture>;
using Framebuffer = GlObject<detail::delete_framebuffer>;
using Query = GlObject<detail::delete_query>;
using Program = GlObject<detail::delete_program>;
using Shader = GlObject<detail::delete_shader>;

inline Buffer make_buffer() { GLuint n = 0; glCreateBuffers(1, &n); return Buffer(n); }
inline VertexArray make_vertex_array() { GLuint n = 0; glCreateVertexArrays(1, &n); return VertexArray(n); }
inline Texture make_texture(GLenum target) { GLuint n = 0; glCreateTextures(target, 1, &n); return Texture(n); }
inline Framebuffer make_framebuffer() { GLuint n = 0; glCreateFramebuffers(1, &n); return Framebuffer(n); }
inline Query make_query(GLenum target) { GLuint n = 0; glCreateQueries(target, 1, &n); return Query(n); }

}  // namespace pyro::gpu
