#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <vector>

#include "ari_social_sim/rendering/camera_model.hpp"
#include "ari_social_sim/rendering/human_figure.hpp"
#include "ari_social_sim/rendering/render_mesh.hpp"
#include "ari_social_sim/rendering/renderer.hpp"

// Where a posed figure appears in a pinhole image, found by projecting the figure's own geometry
// (what the renderer draws) rather than by reading a rendered image: the boxes a face or body
// detector would report on ARI's head camera, computed without rendering.

namespace ari_social_sim::rendering {

/// A box in pixels: columns [x, x + width), rows [y, y + height).
struct PixelBox {
  int x{0};
  int y{0};
  int width{0};
  int height{0};

  double area() const { return static_cast<double>(width) * height; }
  bool empty() const { return width <= 0 || height <= 0; }
  /// Intersection over union; 0 when either box is empty.
  double iou(const PixelBox& other) const;
  bool contains(int u, int v) const { return u >= x && u < x + width && v >= y && v < y + height; }
  /// Whether the box, clipped to a width x height image, meets its border: what it bounds is
  /// cut off there.
  bool reaches_border(int image_width, int image_height) const {
    return x == 0 || y == 0 || x + width == image_width || y + height == image_height;
  }
};

/// The box around the images of `points` (metres, in a frame placed at X_optical_frame), clipped
/// to the image; nullopt when a point is behind the camera or nothing is left inside.
std::optional<PixelBox> projected_box(const PinholeModel& model,
                                      const Eigen::Isometry3d& X_optical_frame,
                                      const std::vector<Eigen::Vector3d>& points);

/// The face's box: around the images of the face's skin that faces the camera
/// (HumanFigure::face_surface) posed at `pose`: what the renderer labels as the face, less what
/// other parts of the figure (ears, a mask) hide. Nullopt when a point is behind the camera, none
/// faces it or the box falls outside the image. Whether the face is turned to the camera is the
/// caller's question: a head seen from the side still shows some skin.
std::optional<PixelBox> face_region(const HumanFigure& figure, const FigurePose& pose,
                                    const PinholeModel& model,
                                    const Eigen::Isometry3d& X_world_optical);

/// The tighter box a face detector draws: around the face's outline (hairline, chin, cheeks;
/// HumanFigure::face_outline) posed at `pose` and projected; the image labels' face box. Nullopt
/// as projected_box.
std::optional<PixelBox> face_outline_region(const HumanFigure& figure, const FigurePose& pose,
                                            const PinholeModel& model,
                                            const Eigen::Isometry3d& X_world_optical);

/// The body's box: around the images of the person's triangles (`vertices` of `mesh`, world
/// coordinates as PeopleFigures poses them) in front of the camera, clipped to the image; nullopt
/// when none is in front or the box falls outside the image.
std::optional<PixelBox> body_region(const RenderMesh& mesh, const VertexRange& vertices,
                                    const PinholeModel& model,
                                    const Eigen::Isometry3d& X_world_optical);

/// The body box (body_region) of `figure` posed at `pose`, for a figure posed outside a mesh.
std::optional<PixelBox> posed_body_region(const HumanFigure& figure, const FigurePose& pose,
                                          const PinholeModel& model,
                                          const Eigen::Isometry3d& X_world_optical);

/// The images of the figure's eyes (HumanFigure::eyes), right eye first; nullopt when either is
/// behind the camera. Not clipped: an eye may lie outside the image.
std::optional<std::array<Eigen::Vector2d, 2>> eye_pixels(const HumanFigure& figure,
                                                         const FigurePose& pose,
                                                         const PinholeModel& model,
                                                         const Eigen::Isometry3d& X_world_optical);

}  // namespace ari_social_sim::rendering
