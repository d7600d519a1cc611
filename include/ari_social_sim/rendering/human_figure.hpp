#pragma once

#include <Eigen/Geometry>
#include <array>
#include <utility>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/rendering/furniture.hpp"
#include "ari_social_sim/rendering/human_appearance.hpp"
#include "ari_social_sim/rendering/render_mesh.hpp"

namespace ari_social_sim::rendering {

/// A figure's pose at one instant.
struct FigurePose {
  core::Pose2 body;  // map frame: below the pelvis (the feet's centre when standing) and heading
  double head_yaw_rad{
      0.0};  // map frame; the head turns to it, at most kMaxHeadTurnRad off the body
  double head_pitch_rad{0.0};  // positive: the head tips down (a nod), about its centre
  double gait_phase_rad{0.0};  // where the legs are in a stride: 0 and pi are mid-stance
  double gait_amplitude{0.0};  // 0 standing still, 1 a brisk walk
  double mouth_open{0.0};      // 0 closed, 1 open as on a stressed syllable
  /// 0 standing, 1 seated (world::PostureState::seated_fraction): the thighs on a seat at
  /// seat_height_m, the feet world::kSeatToFeetM ahead of `body`; in between, standing up or
  /// sitting down (the trunk leans forward, the hips rise).
  double seated{0.0};
  double seat_height_m{kChairSeatHeightM};
  /// 0 arms at rest, 1 gesturing as a speaker does: the forearms raised into the space in front
  /// of the trunk, the dominant hand more; `gesture_beat` in [-1, 1] moves them in beats.
  double gesture{0.0};
  double gesture_beat{0.0};
  /// Standing, which leg bears the weight: +1 the figure's left, -1 its right, 0 both
  /// (WeightShifts); the pelvis moves over that leg and drops on the other side, the free knee
  /// bends, the feet stay put. Fades as the figure walks or sits.
  double weight_side{0.0};
};

/// A person drawn as an articulated solid: feet, lower and upper legs, pelvis, torso, shoulders,
/// upper arms, forearms, hands, neck and a head: skull, jaw and chin, ears, hair and a face set
/// into the skull (brow ridge, eye sockets, eyes, brows, cheekbones, a nose with bridge, tip and
/// nostrils, lips, a mouth that opens, a mask over nose and mouth when worn). Proportions are
/// shares of stature (Drillis and Contini's segment lengths) below the chin and the appearance's
/// head above it. Every part is tessellated once, in its joint's frame; posing moves the parts.
class HumanFigure {
 public:
  static constexpr double kMaxHeadTurnRad = 1.2;

  explicit HumanFigure(const HumanAppearance& look);

  const HumanAppearance& appearance() const { return look_; }

  /// Appends the figure's triangles in `pose`: the face's (head skin and features) labelled
  /// face_label, every other part body_label.
  void append_posed(const FigurePose& pose, float body_label, float face_label,
                    RenderMesh& out) const;

  /// The head in the map: origin at the head's centre, x out of the face, z up.
  Eigen::Isometry3d head_frame(const FigurePose& pose) const;

  /// Points of the face in the head frame: hairline, chin, both cheeks and the nose's tip (which
  /// bounds a face in profile). The face's box in an
  /// image is the box around their images (the tighter box a face detector draws; what a camera
  /// sees of the face is face_surface's box, figure_regions.hpp).
  const std::vector<Eigen::Vector3d>& face_outline() const { return face_outline_; }

  /// The face's vertices in the head frame with their outward normals: every face part's (skin,
  /// eyes, brows, nose, lips, a mask) where the hair does not cover it, the jaw's both closed and
  /// fully open. Those facing a camera are what it sees of the face (face_label's pixels), so their
  /// images bound the face's.
  struct SurfacePoint {
    Eigen::Vector3d point;
    Eigen::Vector3d normal;
  };
  const std::vector<SurfacePoint>& face_surface() const { return face_surface_; }

  /// A hand's centre in the map: the figure's left hand, or its right.
  Eigen::Vector3d hand_centre(const FigurePose& pose, bool left) const;

  /// The irises' centres in the head frame: the figure's right eye, then its left.
  const std::array<Eigen::Vector3d, 2>& eyes() const { return eyes_; }

 private:
  enum Joint {
    kPelvis,
    kHead,
    kJaw,
    kLeftHip,
    kLeftKnee,
    kLeftAnkle,
    kRightHip,
    kRightKnee,
    kRightAnkle,
    kLeftShoulder,
    kLeftElbow,
    kRightShoulder,
    kRightElbow,
    kJointCount
  };
  struct Part {
    Joint joint;
    bool face;
    RenderMesh mesh;  // in the joint's frame
  };
  using JointFrames = std::array<Eigen::Isometry3f, kJointCount>;

  JointFrames joint_frames(const FigurePose& pose) const;
  double gesture_share(const FigurePose& pose, double side) const;
  /// The trunk's frame (the kPelvis joint's: the trunk's parts are placed for a standing figure):
  /// the body's, its hips lowered towards the seat and the trunk leaning as `pose.seated` says.
  /// Height (m) of the hip joints of a figure settled on the seat.
  double seated_hip_z(const FigurePose& pose) const;
  /// How far (rad, forward from straight down) the thigh pitches for the leg to reach from a hip
  /// at (hip_x, hip_z) to an ankle at (ankle_x, ankle_z), in the body's sagittal plane, the knee
  /// bending forward; the leg points straight at an ankle out of its reach.
  double thigh_pitch_rad(double hip_z, double hip_x, double ankle_x, double ankle_z) const;
  Eigen::Isometry3f trunk_frame(const FigurePose& pose, const Eigen::Isometry3f& body) const;
  /// pose.weight_side where the figure stands still, fading to 0 as it walks or sits.
  double standing_load(const FigurePose& pose) const;
  /// How far (m) the hips rise as they move over the leg that bears the weight, for it to stay
  /// straight from the hip to its foot.
  double loaded_hip_rise(const FigurePose& pose, const Eigen::Isometry3f& body) const;
  /// One leg's hip, knee and ankle frames: the standing stance and stride, or, once the figure
  /// sits at all or stands on one leg, the thigh and shin that reach from the hip to the foot on
  /// the floor.
  std::array<Eigen::Isometry3f, 3> leg_frames(const FigurePose& pose, const Eigen::Isometry3f& body,
                                              double side) const;
  std::array<Eigen::Isometry3f, 3> leg_reaching(const Eigen::Isometry3f& body,
                                                const Eigen::Vector3f& hip_point,
                                                const Eigen::Vector3f& ankle_point) const;
  /// The knee and ankle frames below `hip`, the knee bent by knee_flex, the foot on the body's
  /// heading.
  std::array<Eigen::Isometry3f, 3> leg_with_flat_foot(const Eigen::Isometry3f& body,
                                                      const Eigen::Isometry3f& hip,
                                                      double knee_flex) const;
  void add_part(Joint joint, bool face, const RenderPrimitive& primitive);
  void build_legs();
  void build_trunk_and_arms();
  void build_head();
  // build_head's stages. An ellipsoid is (centre, diameters) in the head frame.
  using Ellipsoid = std::pair<Eigen::Vector3d, Eigen::Vector3d>;
  /// How far in front of the head's centre the skin (skull, jaw and chin) is at (y, z) of the head
  /// frame.
  double face_front(double y, double z) const;
  /// Adds a feature set into the face at (y, z): an ellipsoid of `size` (across the skin's normal,
  /// across the face, up), its axis along the skin's normal there, standing `rise` out of the skin.
  /// `roll_rad` turns it about the normal: positive raises its end towards the figure's left.
  void add_face_feature(Joint joint, double y, double z, const Eigen::Vector3d& size, double rise,
                        const Eigen::Vector3f& colour, double roll_rad = 0.0);
  void add_skull_and_jaw();
  std::vector<Ellipsoid> add_hair();  ///< The hair's ellipsoids, which hide the skin inside them.
  void add_ears();
  void add_brows_and_cheekbones();
  void add_eyes();
  void add_mask();
  void add_nose();
  void add_mouth();
  void add_mouth_corners();
  void collect_face_surface(const std::vector<Ellipsoid>& hair);

  HumanAppearance look_;
  // Lengths (m), from the appearance.
  double scale_{1.0};  // stature below the chin / 0.87: a segment of share k is k * scale_ long
  double chin_z_{0.0}, head_centre_z_{0.0}, shoulder_z_{0.0}, hip_z_{0.0};
  double thigh_m_{0.0}, shin_m_{0.0}, upper_arm_m_{0.0}, forearm_m_{0.0}, hand_m_{0.0};
  double hip_joint_y_{0.0}, shoulder_joint_y_{0.0};
  double thigh_radius_m_{0.0};
  Eigen::Vector3d head_radii_{Eigen::Vector3d::Zero()};
  std::vector<Part> parts_;
  std::vector<Ellipsoid> skin_volumes_;  // skull, jaw and chin: features are set into them
  std::vector<Eigen::Vector3d> face_outline_;
  std::vector<SurfacePoint> face_surface_;
  std::array<Eigen::Vector3d, 2> eyes_{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
};

}  // namespace ari_social_sim::rendering
