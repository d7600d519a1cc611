#include "multisample_target.hpp"

#include <string>

#include "ari_social_sim/rendering/renderer.hpp"

namespace ari_social_sim::rendering {
namespace {

// One triangle covering the viewport, from the vertex index alone.
constexpr const char* kFullScreenVertexShader = R"(#version 330 core
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kResolveFragmentShader = R"(#version 330 core
uniform sampler2DMS colour_samples;
uniform sampler2DMS depth_samples;
uniform sampler2DMS label_samples;
uniform int samples;
layout(location = 0) out vec4 out_colour;
layout(location = 1) out float out_depth;
layout(location = 2) out float out_label;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  // The stored colours are display values: average the light they stand for.
  vec3 light = vec3(0.0);
  for (int s = 0; s < samples; ++s) {
    light += pow(texelFetch(colour_samples, pixel, s).rgb, vec3(2.2));
  }
  out_colour = vec4(pow(light / float(samples), vec3(1.0 / 2.2)), 1.0);
  out_depth = texelFetch(depth_samples, pixel, 0).r;
  out_label = texelFetch(label_samples, pixel, 0).r;
}
)";

}  // namespace

MultisampleTarget::MultisampleTarget(int width, int height, int samples)
    : width_(width), height_(height) {
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glGenTextures(kOutputs, textures_);
  const GLenum formats[kOutputs] = {GL_RGBA8, GL_R32F, GL_R32F};
  for (int i = 0; i < kOutputs; ++i) {
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, textures_[i]);
    glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, formats[i], width, height, GL_TRUE);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D_MULTISAMPLE,
                           textures_[i], 0);
  }
  glGenRenderbuffers(1, &depth_buffer_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_buffer_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT32F, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RenderError("a " + std::to_string(samples) + "-sample framebuffer " +
                      std::to_string(width) + "x" + std::to_string(height) + " is incomplete");
  }
  resolve_program_ = link_program(kFullScreenVertexShader, kResolveFragmentShader);
  glUseProgram(resolve_program_);
  const char* names[kOutputs] = {"colour_samples", "depth_samples", "label_samples"};
  for (int i = 0; i < kOutputs; ++i) {
    glUniform1i(glGetUniformLocation(resolve_program_, names[i]), i);
  }
  glUniform1i(glGetUniformLocation(resolve_program_, "samples"), samples);
  glGenVertexArrays(1, &empty_vertex_array_);
}

MultisampleTarget::~MultisampleTarget() {
  glDeleteVertexArrays(1, &empty_vertex_array_);
  glDeleteProgram(resolve_program_);
  glDeleteRenderbuffers(1, &depth_buffer_);
  glDeleteTextures(kOutputs, textures_);
  glDeleteFramebuffers(1, &framebuffer_);
}

void MultisampleTarget::resolve_into(GLuint single_sample_framebuffer, const GLenum* draw_buffers) {
  glBindFramebuffer(GL_FRAMEBUFFER, single_sample_framebuffer);
  glDrawBuffers(kOutputs, draw_buffers);
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glUseProgram(resolve_program_);
  for (int i = 0; i < kOutputs; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, textures_[i]);
  }
  glBindVertexArray(empty_vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace ari_social_sim::rendering
