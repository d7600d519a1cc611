#pragma once

#include "gl_program.hpp"

namespace ari_social_sim::rendering {

/// An off-screen target drawn with several samples per pixel (multisample anti-aliasing), with the
/// same three outputs as the renderer's single-sample framebuffer: colour, optical depth, labels.
/// resolve_into() writes one value per pixel into that framebuffer: colour averaged over the
/// samples in linear light (edges blend as a camera's pixels integrate light), depth and labels
/// taken from sample 0, so that they stay exact values of one surface, never a blend of two.
class MultisampleTarget {
 public:
  /// Throws RenderError when the context cannot make such a target (too many samples).
  MultisampleTarget(int width, int height, int samples);
  ~MultisampleTarget();
  MultisampleTarget(const MultisampleTarget&) = delete;
  MultisampleTarget& operator=(const MultisampleTarget&) = delete;

  GLuint framebuffer() const { return framebuffer_; }
  /// Resolves into `single_sample_framebuffer` (of the same size), writing the attachments that
  /// `draw_buffers` (three, as glDrawBuffers takes them) select. Leaves that framebuffer bound.
  void resolve_into(GLuint single_sample_framebuffer, const GLenum* draw_buffers);

 private:
  static constexpr int kOutputs = 3;
  int width_;
  int height_;
  GLuint framebuffer_{0};
  GLuint textures_[kOutputs]{0, 0, 0};
  GLuint depth_buffer_{0};
  GLuint resolve_program_{0};
  GLuint empty_vertex_array_{0};  // a core context draws only with a vertex array bound
};

}  // namespace ari_social_sim::rendering
