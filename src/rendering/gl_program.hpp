#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

namespace ari_social_sim::rendering {

/// Compiles and links a vertex and a fragment shader into a program of the current context.
/// Throws RenderError with the compiler's or linker's log when either fails.
GLuint link_program(const char* vertex_source, const char* fragment_source);

/// A program of a vertex shader alone whose output `varying` is captured by transform feedback
/// (nothing is rasterised). Throws RenderError as link_program does.
GLuint link_capture_program(const char* vertex_source, const char* varying);

}  // namespace ari_social_sim::rendering
