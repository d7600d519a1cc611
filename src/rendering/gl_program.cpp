#include "gl_program.hpp"

#include <string>

#include "ari_social_sim/rendering/renderer.hpp"

namespace ari_social_sim::rendering {
namespace {

// Throws RenderError with the driver's log when a shader did not compile or a program did not
// link: `get_status` and `get_log` are glGetShaderiv and glGetShaderInfoLog, or the Program pair.
void check_built(GLuint object, GLenum status, void (*get_status)(GLuint, GLenum, GLint*),
                 void (*get_log)(GLuint, GLsizei, GLsizei*, GLchar*), const char* failure) {
  GLint ok = GL_FALSE;
  get_status(object, status, &ok);
  if (ok != GL_TRUE) {
    char log[2048];
    get_log(object, sizeof(log), nullptr, log);
    throw RenderError(std::string(failure) + log);
  }
}

GLuint compile(GLenum stage, const char* source) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  check_built(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog,
              "shader compilation failed: ");
  return shader;
}

void link_or_throw(GLuint program) {
  glLinkProgram(program);
  check_built(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog,
              "shader linking failed: ");
}

}  // namespace

GLuint link_program(const char* vertex_source, const char* fragment_source) {
  const GLuint program = glCreateProgram();
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_source);
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  link_or_throw(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  return program;
}

GLuint link_capture_program(const char* vertex_source, const char* varying) {
  const GLuint program = glCreateProgram();
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source);
  glAttachShader(program, vertex);
  glTransformFeedbackVaryings(program, 1, &varying, GL_INTERLEAVED_ATTRIBS);
  link_or_throw(program);
  glDeleteShader(vertex);
  return program;
}

}  // namespace ari_social_sim::rendering
