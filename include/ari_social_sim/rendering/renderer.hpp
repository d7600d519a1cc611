#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/rendering/camera_model.hpp"
#include "ari_social_sim/rendering/render_mesh.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// No headless OpenGL 3.3 context could be made (no EGL, no Mesa driver, no GPU access).
class RenderError : public core::Error {
 public:
  using core::Error::Error;
};

/// What one pinhole view produced. Row 0 is the top of the image (v = 0).
struct RenderedImage {
  cv::Mat colour;  // CV_8UC3, RGB order
  cv::Mat depth;   // CV_32FC1, metres along the optical z axis; NaN where no surface was hit
  cv::Mat labels;  // CV_16UC1, the label of the mesh seen at each pixel (RenderMesh), 0 for none
};

/// A run of vertices of the dynamic mesh, e.g. one person's figure.
struct VertexRange {
  size_t first{0};
  size_t count{0};
};

struct ViewOptions {
  bool colour{true};
  bool depth{false};
  bool labels{false};
  /// Samples per pixel: 1 draws each pixel from its centre; more anti-alias the colour (depth and
  /// labels stay those of one sample: exact values of one surface).
  int samples{1};
  /// Draws only these vertices of the dynamic mesh and nothing of the static scene: what one
  /// person would cover with nothing in front of them.
  std::optional<VertexRange> only_dynamic;
  double near_m{0.02};  // clip planes of the view; sensor ranges are applied by the caller
  double far_m{100.0};
};

/// Headless OpenGL renderer of primitives into colour and metric depth (off-screen framebuffers).
/// It opens its own EGL context: a GPU's when EGL lists a hardware device, otherwise Mesa's
/// surfaceless platform (llvmpipe, on the CPU). The scene is split in a static part, uploaded once
/// (walls, furniture, floor), and a dynamic part replaced every tick (people, the robot).
/// Not thread-safe: use one Renderer from one thread at a time.
class Renderer {
 public:
  /// Throws RenderError naming what failed when no context can be created.
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& device_name() const;

  void set_static_primitives(const std::vector<RenderPrimitive>& primitives);
  void set_dynamic_primitives(const std::vector<RenderPrimitive>& primitives);
  /// The dynamic part as triangles already in the world (posed figures, then primitives).
  void set_dynamic_mesh(const RenderMesh& mesh);

  /// Renders the scene seen from an optical frame (REP-103) through an ideal pinhole. The images
  /// in `out` are reallocated only when the size changes.
  void render(const PinholeModel& model, const Eigen::Isometry3d& X_world_optical,
              const ViewOptions& options, RenderedImage& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ari_social_sim::rendering
