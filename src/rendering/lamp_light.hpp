#pragma once

#include <Eigen/Core>
#include <vector>

#include "gl_program.hpp"

namespace ari_social_sim::rendering {

/// GLSL: the light the ceiling's lamps give a vertex, `vec4 lamp_light(vec3 position, vec3
/// normal)`: irradiance in x, and in yzw the direction it comes from (unnormalised, weighted by
/// what each lamp brings). Reads `uniform int lamp_count; uniform vec3 lamps[32];` (the centres of
/// the lamps' emitting faces). Shared by the renderer's vertex shader and LampLightBake, so that a
/// vertex lit once and a vertex lit every frame are lit alike.
extern const char* const kLampLightGlsl;

/// Lights a static mesh's vertices by every lamp once, on the GPU (transform feedback through
/// kLampLightGlsl), instead of every frame: the room's lamps and vertices do not move, and
/// llvmpipe shades vertices on the rendering thread. Needs the renderer's context current.
class LampLightBake {
 public:
  LampLightBake();
  ~LampLightBake();
  LampLightBake(const LampLightBake&) = delete;
  LampLightBake& operator=(const LampLightBake&) = delete;

  /// Fills `light` (a GL buffer) with lamp_light's vec4 for each of the `vertex_count` vertices of
  /// `vertex_array` (positions at attribute 0, normals at 1), summed over all `lamps`, 32 at a
  /// time.
  void bake(GLuint vertex_array, GLsizei vertex_count, const std::vector<Eigen::Vector3f>& lamps,
            GLuint light) const;

  static constexpr size_t kLampsPerPass = 32;

 private:
  GLuint program_{0};
  // A draw needs a complete framebuffer even when nothing is rasterised; the context has none
  // until a view is rendered.
  GLuint framebuffer_{0};
  GLuint renderbuffer_{0};
  GLint lamp_count_location_{-1};
  GLint lamps_location_{-1};
};

}  // namespace ari_social_sim::rendering
