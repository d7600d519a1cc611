#include "gl_program.hpp"

#include <string>

#include "ari_social_sim/rendering/renderer.hpp"

namespace ari_social_sim::rendering {
namespace {

GLuint compile(GLenum stage, const char* source) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    throw RenderError(std::string("shader compilation failed: ") + log);
  }
  return shader;
}

void link_or_throw(GLuint program) {
  glLinkProgram(program);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048];
    glGetProgramInfoLog(program, sizeof(log), nullptr, log);
    throw RenderError(std::string("shader linking failed: ") + log);
  }
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
