#include "egl_context.hpp"

#include <EGL/eglext.h>

#include <cstring>
#include <sstream>

#include "ari_social_sim/rendering/renderer.hpp"

namespace ari_social_sim::rendering {
namespace {

template <class Function>
Function egl_function(const char* name) {
  return reinterpret_cast<Function>(eglGetProcAddress(name));
}

std::string hex(EGLint code) {
  std::ostringstream out;
  out << "0x" << std::hex << code;
  return out.str();
}

}  // namespace

EglContext::EglContext() {
  const auto get_platform_display =
      egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  const auto query_devices = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  const auto query_device_string =
      egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  if (get_platform_display == nullptr) {
    throw RenderError("EGL has no eglGetPlatformDisplayEXT (is libegl-mesa0 installed?)");
  }
  std::string failures;

  // A hardware device (GPU) when there is one. Mesa lists llvmpipe as a device too, marked by
  // EGL_MESA_device_software; that one is taken through the surfaceless platform below.
  if (query_devices != nullptr && query_device_string != nullptr) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (query_devices(16, devices, &count) == EGL_TRUE) {
      for (EGLint i = 0; i < count; ++i) {
        const char* extensions = query_device_string(devices[i], EGL_EXTENSIONS);
        if (extensions != nullptr && std::strstr(extensions, "EGL_MESA_device_software")) {
          continue;
        }
        const EGLDisplay display =
            get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (try_display(display, "EGL device " + std::to_string(i), failures)) {
          return;
        }
      }
    }
  }
  const EGLDisplay surfaceless =
      get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (try_display(surfaceless, "Mesa surfaceless platform", failures)) {
    return;
  }
  throw RenderError("no headless OpenGL 3.3 context: " + failures);
}

bool EglContext::try_display(EGLDisplay display, const std::string& what, std::string& failures) {
  auto fail = [&](const std::string& step) {
    failures += what + ": " + step + " failed (EGL error " + hex(eglGetError()) + "); ";
    return false;
  };
  if (display == EGL_NO_DISPLAY) {
    return fail("eglGetPlatformDisplayEXT");
  }
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
    return fail("eglInitialize");
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    return fail("eglBindAPI(EGL_OPENGL_API)");
  }
  const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                      EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  if (eglChooseConfig(display, config_attributes, &config, 1, &config_count) != EGL_TRUE ||
      config_count < 1) {
    return fail("eglChooseConfig (desktop OpenGL)");
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) {
    return fail("eglCreateContext (OpenGL 3.3 core)");
  }
  // Rendering goes to framebuffer objects only, so no surface is bound
  // (EGL_KHR_surfaceless_context).
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    eglDestroyContext(display, context);
    return fail("eglMakeCurrent without a surface");
  }
  display_ = display;
  context_ = context;
  description_ = what;
  return true;
}

EglContext::~EglContext() {
  // The display is left initialised: EGL shares one display per platform in a process, and
  // eglTerminate would pull it from under any other Renderer.
  if (eglGetCurrentContext() == context_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  eglDestroyContext(display_, context_);
}

void EglContext::make_current() const {
  if (eglGetCurrentContext() != context_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
  }
}

}  // namespace ari_social_sim::rendering
