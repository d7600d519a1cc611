#include "lamp_light.hpp"

#include <algorithm>
#include <string>

namespace ari_social_sim::rendering {

// Light from the ceiling's lamp panels at a vertex: each a downward Lambertian emitter (intensity
// falling with the cosine from straight down), irradiance with the cosine of incidence over the
// squared distance; and the mean direction it comes from, weighted the same way.
const char* const kLampLightGlsl = R"(
uniform int lamp_count;
uniform vec3 lamps[32];

vec4 lamp_light(vec3 position, vec3 normal) {
  vec4 light = vec4(0.0);
  for (int i = 0; i < lamp_count; ++i) {
    vec3 d = lamps[i] - position;
    float distance2 = max(dot(d, d), 0.04);
    vec3 l = d * inversesqrt(distance2);
    float arriving = max(l.z, 0.0) / distance2;
    light.x += arriving * max(dot(normal, l), 0.0);
    light.yzw += arriving * l;
  }
  return light;
}
)";

namespace {

const std::string kCaptureShader = std::string(R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
out vec4 baked_light;
)") + kLampLightGlsl + R"(
void main() {
  baked_light = lamp_light(position, normal);
  gl_Position = vec4(0.0);
}
)";

}  // namespace

LampLightBake::LampLightBake()
    : program_(link_capture_program(kCaptureShader.c_str(), "baked_light")),
      lamp_count_location_(glGetUniformLocation(program_, "lamp_count")),
      lamps_location_(glGetUniformLocation(program_, "lamps")) {
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(1, &renderbuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer_);
}

LampLightBake::~LampLightBake() {
  glDeleteRenderbuffers(1, &renderbuffer_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteProgram(program_);
}

void LampLightBake::bake(GLuint vertex_array, GLsizei vertex_count,
                         const std::vector<Eigen::Vector3f>& lamps, GLuint light) const {
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "glUniform3fv reads packed xyz");
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(vertex_count) * 4 * sizeof(float);
  std::vector<float> sum(static_cast<size_t>(vertex_count) * 4, 0.0f);
  if (vertex_count > 0 && !lamps.empty()) {
    // Captured into a buffer of its own: `light` is the mesh's vertex attribute, which a draw
    // may not read while transform feedback writes it.
    GLuint captured = 0;
    glGenBuffers(1, &captured);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, captured);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captured);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glUseProgram(program_);
    glBindVertexArray(vertex_array);
    glEnable(GL_RASTERIZER_DISCARD);
    std::vector<float> pass(sum.size());
    for (size_t first = 0; first < lamps.size(); first += kLampsPerPass) {
      const auto count = static_cast<GLsizei>(std::min(kLampsPerPass, lamps.size() - first));
      glUniform1i(lamp_count_location_, count);
      glUniform3fv(lamps_location_, count, lamps[first].data());
      glBeginTransformFeedback(GL_POINTS);
      glDrawArrays(GL_POINTS, 0, vertex_count);
      glEndTransformFeedback();
      glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, bytes, pass.data());
      std::transform(sum.begin(), sum.end(), pass.begin(), sum.begin(), std::plus<float>());
    }
    glDisable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glDeleteBuffers(1, &captured);
  }
  glBindBuffer(GL_ARRAY_BUFFER, light);
  glBufferData(GL_ARRAY_BUFFER, bytes, sum.data(), GL_STATIC_DRAW);
}

}  // namespace ari_social_sim::rendering
