#pragma once

#include <EGL/egl.h>

#include <string>

namespace ari_social_sim::rendering {

/// A desktop OpenGL 3.3 core context without any window or surface. Tries EGL's hardware devices
/// first (a GPU), then Mesa's surfaceless platform, which runs llvmpipe on the CPU.
/// Throws RenderError with the EGL error of each attempt when none works.
class EglContext {
 public:
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  /// Binds the context to the calling thread (a no-op when it already is).
  void make_current() const;
  /// Which platform and device was taken, for logs and docs.
  const std::string& description() const { return description_; }

 private:
  bool try_display(EGLDisplay display, const std::string& what, std::string& failures);

  EGLDisplay display_{EGL_NO_DISPLAY};
  EGLContext context_{EGL_NO_CONTEXT};
  std::string description_;
};

}  // namespace ari_social_sim::rendering
