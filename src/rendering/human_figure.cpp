#include "ari_social_sim/rendering/human_figure.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/smoothstep.hpp"
#include "ari_social_sim/world/posture.hpp"

namespace ari_social_sim::rendering {
namespace {

// Facets around the axis: limbs are narrow in any image, the head is what face detectors read.
constexpr int kLimbSegments = 8;
constexpr int kTrunkSegments = 12;
constexpr int kHeadSegments = 16;
constexpr int kFeatureSegments = 6;

// Segment lengths and heights as shares of stature (Drillis and Contini, 1966).
constexpr double kChinShare = 0.870;
constexpr double kShoulderShare = 0.818;
constexpr double kHipShare = 0.530;
constexpr double kKneeShare = 0.285;
constexpr double kAnkleShare = 0.039;
constexpr double kUpperArmShare = 0.186;
constexpr double kForearmShare = 0.146;
constexpr double kHandShare = 0.108;
constexpr double kShoulderWidthShare = 0.259;
constexpr double kHipWidthShare = 0.191;
constexpr double kFootLengthShare = 0.152;
constexpr double kFootWidthShare = 0.055;

// How far the limbs swing at a gait amplitude of 1 (rad).
constexpr double kHipSwingRad = 0.42;
constexpr double kKneeFlexRad = 0.75;
constexpr double kShoulderSwingRad = 0.38;
constexpr double kArmAbductionRad = 0.14;     // arms hang a little away from the body
constexpr double kStanceAbductionRad = 0.07;  // standing feet a little apart
constexpr double kJawDropShare = 0.06;        // of the head's height, the mouth fully open
// Sitting and rising: the trunk leans forward by up to kRiseLeanRad halfway through the change
// (about 35 deg of trunk flexion; docs/cameras.md), and reclines against the backrest by
// kSeatedReclineRad once seated; the hips stay on the seat for the first kHipsStillShare of a
// rise. Seated, the upper arms tilt forward and the elbows bend so the hands rest on the thighs.
constexpr double kRiseLeanRad = 0.6;
constexpr double kSeatedReclineRad = 0.08;
constexpr double kHipsStillShare = 0.3;
constexpr double kSeatedArmPitchRad = 0.4;
constexpr double kSeatedElbowFlexRad = 1.0;
constexpr double kSeatFrontM = 0.2;  // hips to the seat's front edge: a chair 0.45 m deep
// Standing with the weight on one leg (FigurePose::weight_side), the pelvis and the trunk above it
// move kPelvisShiftM over that leg, about the sideways shift of the centre of pressure between the
// two legs (Duarte and Zatsiorsky, 1999: 22 mm); the pelvis tips down on the free side by
// kPelvisDropRad about the hip it rests on, so the free knee bends a little, the feet staying put.
constexpr double kPelvisShiftM = 0.03;
constexpr double kPelvisDropRad = 0.07;
// Gestures while speaking: the upper arm forward by kGestureArmPitchRad and the elbow bent by
// kGestureElbowFlexRad more than at rest bring the forearm up in front of the trunk, where most
// conversational gestures are made (McNeill's central gesture space); beats move both by a
// fraction. The non-dominant hand gestures at kOtherHandShare of the dominant one's amplitude.
constexpr double kGestureArmPitchRad = 0.45;
constexpr double kGestureElbowFlexRad = 1.1;
constexpr double kBeatShare = 0.1;
constexpr double kOtherHandShare = 0.5;

// The face in shares of the head's height (chin to crown; the head frame's origin is halfway),
// from adult means (Farkas, 1994): the nasion 0.04 above the middle, the nose 0.23 long (nasion to
// subnasale) with its tip 0.087 out of the face and its wings 0.15 wide, pupils 0.27 apart, ears
// 0.27 long.
constexpr double kNasionShare = 0.04;
constexpr double kNoseTipZ = -0.15;
constexpr double kNoseTipRise = 0.087;
constexpr double kAlarShare = 0.05;
constexpr double kEyeShare = 0.137;
constexpr double kEarLengthShare = 0.27;
// Expressions: how far anger or distress tilts the brows, joy or distress turns the mouth's
// corners.
constexpr double kBrowTiltRad = 0.25;
constexpr double kMouthCornerTurnRad = 0.5;

RenderPrimitive shape(PrimitiveShape kind, const Eigen::Vector3d& centre,
                      const Eigen::Vector3d& size, const Eigen::Vector3f& colour, int segments) {
  RenderPrimitive primitive;
  primitive.shape = kind;
  primitive.X_world_shape = Eigen::Translation3d(centre) * Eigen::Isometry3d::Identity();
  primitive.size = size;
  primitive.colour = colour;
  primitive.round_segments = segments;
  return primitive;
}

RenderPrimitive glossy(RenderPrimitive primitive) {
  primitive.surface = Surface::kSkin;
  return primitive;
}

// Clothes: their folds are drawn in the part's own frame, so they move with it.
RenderPrimitive cloth(RenderPrimitive primitive) {
  primitive.surface = Surface::kCloth;
  return primitive;
}

Eigen::Vector3f darker(const Eigen::Vector3f& colour, float factor) {
  return colour * factor;
}
Eigen::Vector3f lighter(const Eigen::Vector3f& colour, float factor) {
  return (colour * factor).cwiseMin(1.0f);
}

Eigen::Isometry3f rotation_y(double angle) {
  return Eigen::Isometry3f(Eigen::AngleAxisf(static_cast<float>(angle), Eigen::Vector3f::UnitY()));
}
Eigen::Isometry3f rotation_x(double angle) {
  return Eigen::Isometry3f(Eigen::AngleAxisf(static_cast<float>(angle), Eigen::Vector3f::UnitX()));
}

// Positive: forward. Seated fraction in [0, 1].
double trunk_lean_rad(double seated) {
  return kRiseLeanRad * std::sin(M_PI * seated) - kSeatedReclineRad * seated;
}

Eigen::Isometry3f translation(double x, double y, double z) {
  return Eigen::Isometry3f(
      Eigen::Translation3f(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)));
}

}  // namespace

HumanFigure::HumanFigure(const HumanAppearance& look) : look_(look) {
  chin_z_ = look.height_m - look.head_height_m;
  scale_ = chin_z_ / kChinShare;
  head_centre_z_ = chin_z_ + 0.5 * look.head_height_m;
  shoulder_z_ = kShoulderShare * scale_;
  hip_z_ = kHipShare * scale_;
  thigh_m_ = (kHipShare - kKneeShare) * scale_;
  shin_m_ = (kKneeShare - kAnkleShare) * scale_;
  upper_arm_m_ = kUpperArmShare * scale_;
  forearm_m_ = kForearmShare * scale_;
  hand_m_ = kHandShare * scale_;
  const double shoulder_width =
      kShoulderWidthShare * scale_ * look.build * (look.female_build ? 0.92 : 1.0);
  shoulder_joint_y_ = 0.5 * shoulder_width - 0.03 * scale_;
  thigh_radius_m_ = 0.045 * scale_ * look.build;
  hip_joint_y_ = 0.25 * kHipWidthShare * scale_ * look.build * (look.female_build ? 1.05 : 1.0);
  // Chin to crown is the head's height; it is 0.85 of that deep and 0.68 of that wide.
  head_radii_ = 0.5 * look.head_height_m * Eigen::Vector3d(0.85, 0.68, 1.0);
  build_legs();
  build_trunk_and_arms();
  build_head();
}

void HumanFigure::add_part(Joint joint, bool face, const RenderPrimitive& primitive) {
  Part part{joint, face, {}};
  append_primitive(primitive, part.mesh);
  parts_.push_back(std::move(part));
}

void HumanFigure::build_legs() {
  const double s = scale_;
  const double thigh_radius = thigh_radius_m_;
  const double shin_radius = 0.034 * s * look_.build;
  for (const auto& [hip, knee, ankle] :
       {std::array<Joint, 3>{kLeftHip, kLeftKnee, kLeftAnkle},
        std::array<Joint, 3>{kRightHip, kRightKnee, kRightAnkle}}) {
    add_part(hip, false,
             cloth(shape(PrimitiveShape::kCylinder, {0.0, 0.0, -0.5 * thigh_m_},
                         {2.0 * thigh_radius, 2.0 * thigh_radius, thigh_m_ + thigh_radius},
                         look_.trousers, kLimbSegments)));
    add_part(knee, false,
             cloth(shape(PrimitiveShape::kCylinder, {0.0, 0.0, -0.5 * shin_m_},
                         {2.0 * shin_radius, 2.0 * shin_radius, shin_m_ + shin_radius},
                         darker(look_.trousers, 0.95f), kLimbSegments)));
    const double foot_length = kFootLengthShare * s;
    // From the sole on the floor (when standing) to 2 cm above the ankle.
    const double foot_height = kAnkleShare * s + 0.02;
    add_part(ankle, false,
             shape(PrimitiveShape::kBox, {0.3 * foot_length, 0.0, 0.02 - 0.5 * foot_height},
                   {foot_length, kFootWidthShare * s, foot_height}, look_.shoes, kLimbSegments));
  }
}

void HumanFigure::build_trunk_and_arms() {
  const double s = scale_;
  const double width = (look_.female_build ? 0.19 : 0.205) * s * look_.build;
  const double depth = 0.13 * s * look_.build;
  const double hip_width = kHipWidthShare * s * look_.build * (look_.female_build ? 1.05 : 1.0);
  // Pelvis in the trousers' colour, torso and shoulders in the top's.
  add_part(kPelvis, false,
           cloth(shape(PrimitiveShape::kSphere, {0.0, 0.0, hip_z_ + 0.02 * s},
                       {depth * 0.95, std::max(width, hip_width * 0.9), 0.12 * s}, look_.trousers,
                       kTrunkSegments)));
  const double torso_bottom = hip_z_ + 0.03 * s;
  const double torso_top = shoulder_z_ - 0.04 * s;
  add_part(kPelvis, false,
           cloth(shape(PrimitiveShape::kCylinder, {0.0, 0.0, 0.5 * (torso_bottom + torso_top)},
                       {depth, width, torso_top - torso_bottom}, look_.top, kTrunkSegments)));
  // Chest and seat give the side view its curves: the chest ahead of the waist, the seat behind.
  add_part(kPelvis, false,
           cloth(shape(PrimitiveShape::kSphere, {0.015 * s, 0.0, 0.70 * s},
                       {depth * 1.15, width * 0.9, 0.22 * s}, look_.top, kTrunkSegments)));
  add_part(kPelvis, false,
           cloth(shape(PrimitiveShape::kSphere, {-0.02 * s, 0.0, hip_z_ - 0.01 * s},
                       {depth * 1.1, std::max(width, hip_width * 0.9), 0.16 * s}, look_.trousers,
                       kTrunkSegments)));
  add_part(kPelvis, false,
           shape(PrimitiveShape::kSphere, {0.0, 0.0, torso_top},
                 {depth * 0.95, 2.0 * (shoulder_joint_y_ + 0.025 * s), 0.09 * s}, look_.top,
                 kTrunkSegments));
  // The trapezius slopes from the shoulders up to the neck: the head-and-shoulders outline people
  // detectors look for.
  add_part(kPelvis, false,
           shape(PrimitiveShape::kSphere, {-0.01 * s, 0.0, shoulder_z_ - 0.005 * s},
                 {depth * 0.8, 1.3 * shoulder_joint_y_, 0.09 * s}, look_.top, kTrunkSegments));
  // Neck from inside the shoulders to inside the head.
  const double neck_bottom = shoulder_z_ - 0.03 * s;
  const double neck_top = chin_z_ + 0.3 * look_.head_height_m;
  add_part(kPelvis, false,
           shape(PrimitiveShape::kCylinder, {-0.01 * s, 0.0, 0.5 * (neck_bottom + neck_top)},
                 {0.062 * s, 0.062 * s, neck_top - neck_bottom}, darker(look_.skin, 0.9f),
                 kLimbSegments));

  const double upper_arm_radius = 0.031 * s * look_.build;
  const double forearm_radius = 0.025 * s * look_.build;
  for (const auto& [shoulder, elbow] : {std::array<Joint, 2>{kLeftShoulder, kLeftElbow},
                                        std::array<Joint, 2>{kRightShoulder, kRightElbow}}) {
    add_part(shoulder, false,
             cloth(shape(
                 PrimitiveShape::kCylinder, {0.0, 0.0, -0.5 * upper_arm_m_},
                 {2.0 * upper_arm_radius, 2.0 * upper_arm_radius, upper_arm_m_ + upper_arm_radius},
                 look_.top, kLimbSegments)));
    RenderPrimitive forearm =
        shape(PrimitiveShape::kCylinder, {0.0, 0.0, -0.5 * forearm_m_},
              {2.0 * forearm_radius, 2.0 * forearm_radius, forearm_m_ + forearm_radius},
              look_.short_sleeves ? look_.skin : look_.top, kLimbSegments);
    add_part(elbow, false, look_.short_sleeves ? forearm : cloth(forearm));
    add_part(elbow, false,
             shape(PrimitiveShape::kSphere, {0.0, 0.0, -forearm_m_ - 0.45 * hand_m_},
                   {0.045 * s, 0.028 * s, hand_m_}, look_.skin, kFeatureSegments));
  }
}

void HumanFigure::build_head() {
  const double h = look_.head_height_m;
  const Eigen::Vector3d& r = head_radii_;
  add_skull_and_jaw();
  add_ears();
  const std::vector<Ellipsoid> hair = add_hair();
  // The face box: hairline to chin, side to side of the head at the eyes, out to the nose's tip.
  face_outline_ = {{face_front(0.0, 0.3 * h), 0.0, 0.3 * h},
                   {face_front(0.0, -0.47 * h), 0.0, -0.5 * h},
                   {0.0, r.y(), 0.0},
                   {0.0, -r.y(), 0.0},
                   {face_front(0.0, kNoseTipZ * h) + kNoseTipRise * h, 0.0, kNoseTipZ * h}};
  add_brows_and_cheekbones();
  add_eyes();
  if (look_.mask) {
    add_mask();
  } else {
    add_nose();
    add_mouth();
  }
  collect_face_surface(hair);
}

double HumanFigure::face_front(double y, double z) const {
  double front = 0.0;
  for (const auto& [centre, diameters] : skin_volumes_) {
    const Eigen::Vector3d radii = 0.5 * diameters;
    const double dy = (y - centre.y()) / radii.y(), dz = (z - centre.z()) / radii.z();
    const double inside = 1.0 - dy * dy - dz * dz;
    if (inside > 0.0) {
      front = std::max(front, centre.x() + radii.x() * std::sqrt(inside));
    }
  }
  return front;
}

void HumanFigure::add_face_feature(Joint joint, double y, double z, const Eigen::Vector3d& size,
                                   double rise, const Eigen::Vector3f& colour, double roll_rad) {
  // The skin's outward normal from the slope of face_front.
  const double step = 0.002 * look_.head_height_m;
  const Eigen::Vector3d normal =
      Eigen::Vector3d(1.0, -(face_front(y + step, z) - face_front(y - step, z)) / (2.0 * step),
                      -(face_front(y, z + step) - face_front(y, z - step)) / (2.0 * step))
          .normalized();
  const Eigen::Vector3d up = (Eigen::Vector3d::UnitZ() - normal.z() * normal).normalized();
  Eigen::Matrix3d axes;
  axes << normal, up.cross(normal), up;
  const Eigen::Vector3d skin(face_front(y, z), y, z);
  RenderPrimitive feature =
      shape(PrimitiveShape::kSphere, Eigen::Vector3d::Zero(), size, colour, kFeatureSegments);
  // Skin-coloured features (brow ridge, cheekbones) shine as the skin they are set into does.
  if (colour == look_.skin) {
    feature = glossy(feature);
  }
  feature.X_world_shape = Eigen::Translation3d(skin + (rise - 0.5 * size.x()) * normal) *
                          Eigen::Isometry3d(axes) *
                          Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitX());
  add_part(joint, true, feature);
}

// The skull is the head's ellipsoid; the jaw, narrower, and the chin ahead of it bring the lower
// face forward of it, so that the jaw line turns back to the neck under the chin.
void HumanFigure::add_skull_and_jaw() {
  const double h = look_.head_height_m;
  skin_volumes_ = {{Eigen::Vector3d::Zero(), 2.0 * head_radii_},
                   {Eigen::Vector3d(0.15 * h, 0.0, -0.3 * h), Eigen::Vector3d(0.4, 0.42, 0.4) * h},
                   {Eigen::Vector3d(0.26 * h, 0.0, -0.4 * h), Eigen::Vector3d(0.2, 0.26, 0.2) * h}};
  for (const auto& [centre, diameters] : skin_volumes_) {
    add_part(kHead, true,
             glossy(shape(PrimitiveShape::kSphere, centre, diameters, look_.skin, kHeadSegments)));
  }
}

// Ears from brow to nose base, with the darker hollow of the concha.
void HumanFigure::add_ears() {
  const double h = look_.head_height_m;
  const double y = head_radii_.y();
  for (double side : {-1.0, 1.0}) {
    add_part(kHead, false,
             shape(PrimitiveShape::kSphere, {-0.05 * h, side * y, -0.045 * h},
                   {0.1 * h, 0.05 * h, kEarLengthShare * h}, darker(look_.skin, 0.93f),
                   kFeatureSegments));
    add_part(kHead, false,
             shape(PrimitiveShape::kSphere, {-0.04 * h, side * (y + 0.018 * h), -0.06 * h},
                   {0.05 * h, 0.02 * h, 0.1 * h}, darker(look_.skin, 0.6f), kFeatureSegments));
  }
}

std::vector<HumanFigure::Ellipsoid> HumanFigure::add_hair() {
  const double h = look_.head_height_m;
  const Eigen::Vector3d& r = head_radii_;
  // Hair: a cap over the crown from the forehead's hairline and one over the back of the head down
  // to the nape, whose edges draw the hairline around the head; sideburns in front of the ears
  // down to the tragus. In profile the temple and sideburn are dark beside the eye, as face
  // detectors trained on real profiles expect.
  std::vector<Ellipsoid> hair;
  auto add = [&](const Eigen::Vector3d& centre, const Eigen::Vector3d& diameters, int segments) {
    hair.emplace_back(centre, diameters);
    add_part(kHead, false, shape(PrimitiveShape::kSphere, centre, diameters, look_.hair, segments));
  };
  if (look_.hair_style != HairStyle::kBald) {
    // The front cap sits back as far as the hairline has receded.
    add(Eigen::Vector3d((-0.01 - look_.hairline_recession) * h, 0.0, 0.15 * h),
        Eigen::Vector3d(0.75, 0.76, 0.8) * h, kHeadSegments);
    add(Eigen::Vector3d(-0.19 * h, 0.0, 0.08 * h), Eigen::Vector3d(0.55, 0.74, 0.82) * h,
        kHeadSegments);
  } else {
    // Bald men keep a fringe over the back and the sides below the crown (male pattern baldness).
    add(Eigen::Vector3d(-0.12 * h, 0.0, -0.1 * h), Eigen::Vector3d(0.66, 0.72, 0.74) * h,
        kHeadSegments);
  }
  for (double side : {-1.0, 1.0}) {
    add(Eigen::Vector3d(0.06 * h, side * 0.3 * h, 0.05 * h), Eigen::Vector3d(0.14, 0.1, 0.26) * h,
        kFeatureSegments);
  }
  // Long hair falls from the crown to the shoulders as one volume, about as wide and deep as the
  // back cap, whose lower half it covers. Hung from the nape (its top 0.1 of the head above the
  // eyes), it showed from behind as a second ball under the crown's with a dark crease between, on
  // which the frontal cascades with equalizeHist fired.
  if (look_.hair_style == HairStyle::kLong) {
    add(Eigen::Vector3d(-0.45 * r.x(), 0.0, -0.25 * h),
        Eigen::Vector3d(1.3 * r.x(), 2.0 * r.y() * 1.08, 1.5 * h), kHeadSegments);
  }
  return hair;
}

// The brow ridge over the eyes and the cheekbones under them stand out of the skull, so that the
// eyes lie in sockets. Detectors read a face by its contrasts (Viola and Jones' features): eye
// sockets and brows darker than the forehead and the cheeks, a bright nose bridge between the
// eyes, a dark mouth.
void HumanFigure::add_brows_and_cheekbones() {
  const double h = look_.head_height_m;
  const Eigen::Vector3f& skin = look_.skin;
  add_face_feature(kHead, 0.0, 0.08 * h, Eigen::Vector3d(0.12, 0.12, 0.09) * h, 0.02 * h, skin);
  // Brows darker than the skin whatever the hair's colour: fair hair has darker brows.
  const Eigen::Vector3f brow = darker(look_.hair, 0.5f).cwiseMin(darker(skin, 0.35f));
  // Expressions move the brows: anger draws their inner ends down and together, distress raises
  // them; joy lifts the brows a little.
  double inner_drop = 0.0, lift = 0.0;
  switch (look_.emotion) {
    case model::Emotion::kAngry:
      inner_drop = kBrowTiltRad, lift = -0.012 * h;
      break;
    case model::Emotion::kDisturbed:
      inner_drop = -kBrowTiltRad;
      break;
    case model::Emotion::kHappy:
      lift = 0.008 * h;
      break;
    case model::Emotion::kNeutral:
      break;
  }
  for (double side : {-1.0, 1.0}) {
    // Brows lie on the ridge, standing out of it by a few millimetres.
    add_face_feature(kHead, side * 0.12 * h, 0.1 * h, Eigen::Vector3d(0.14, 0.22, 0.1) * h,
                     0.024 * h, skin);
    add_face_feature(kHead, side * 0.12 * h, 0.11 * h + lift, Eigen::Vector3d(0.1, 0.2, 0.045) * h,
                     0.028 * h, brow, side * inner_drop);
    // The cheekbone is a broad, thin swell of the skin, 0.006 of the head proud, whose edge meets
    // the skin at 10 to 16 degrees. Rounder and 0.02 proud (40 degrees), it showed as a bright
    // disc under the eye, and the default frontal cascade took the near eye over its disc for a
    // face on heads turned 45 to 80 degrees; without it, the profile cascade lost the bright skin
    // under the eye it looks for.
    add_face_feature(kHead, side * 0.19 * h, -0.1 * h, Eigen::Vector3d(0.04, 0.24, 0.14) * h,
                     0.006 * h, skin);
  }
}

// Eyes at the head's middle, a pupil distance of 0.27 h apart, in dark sockets.
void HumanFigure::add_eyes() {
  const double h = look_.head_height_m;
  for (double side : {-1.0, 1.0}) {
    const double y = side * kEyeShare * h;
    add_face_feature(kHead, y, 0.02 * h, Eigen::Vector3d(0.1, 0.22, 0.15) * h, 0.006 * h,
                     darker(look_.skin, 0.4f));
    // The white stands less out of the skin than the iris, under the lid: turned 45 to 60
    // degrees, the far eye then shows less white and reads less as a frontal eye. It is an
    // off-white in the lid's and the brow's shade (0.7 of white, as cameras see the sclera
    // indoors); drawn near white (0.9), it gave the eyes a contrast no real face has under
    // ceiling lamps, on which the default frontal cascade took turned heads for faces.
    add_face_feature(kHead, y, 0.0, Eigen::Vector3d(0.06, 0.13, 0.06) * h, 0.008 * h,
                     Eigen::Vector3f(0.72f, 0.7f, 0.67f));
    add_face_feature(kHead, y, 0.0, Eigen::Vector3d(0.04, 0.06, 0.06) * h, 0.016 * h,
                     look_.iris * 0.5f);
    // The upper lid from the eye's top half up to its crease: skin in the brow's shadow, a little
    // darker than the skin (0.9). Darker (0.6, then 0.8), it read as a second brow under the
    // first, most under ceiling lamps. Ending lower (0.04 of the head tall), it left a band of the
    // dark socket between lid and brow, which from the side stacked under the brow as a second
    // bar; the default frontal cascade took either pair for eyes on the near side of turned heads.
    add_face_feature(kHead, y, 0.022 * h, Eigen::Vector3d(0.06, 0.15, 0.05) * h, 0.02 * h,
                     darker(look_.skin, 0.9f));
    // The outer corner with the lashes, what marks the eye in profile.
    add_face_feature(kHead, y + side * 0.065 * h, 0.005 * h, Eigen::Vector3d(0.08, 0.08, 0.06) * h,
                     0.012 * h, darker(look_.skin, 0.3f));
    eyes_[side < 0.0 ? 0 : 1] = Eigen::Vector3d(face_front(y, 0.0) + 0.016 * h, y, 0.0);
  }
}

// Over nose and mouth, ear to ear: a shell in front of the lower face.
void HumanFigure::add_mask() {
  const double h = look_.head_height_m;
  const Eigen::Vector3d& r = head_radii_;
  add_part(
      kHead, true,
      shape(PrimitiveShape::kSphere, {0.35 * r.x(), 0.0, -0.27 * h},
            {2.0 * 0.82 * r.x(), 2.0 * r.y() * 0.98, 0.5 * h}, look_.mask_colour, kHeadSegments));
  // A surgical mask's three pleats: bands standing 3 mm proud of the mask, following it.
  for (const double z : {-0.17 * h, -0.27 * h, -0.37 * h}) {
    const double dz = (z + 0.27 * h) / (0.25 * h);
    const double across = std::sqrt(1.0 - dz * dz);
    add_part(kHead, true,
             shape(PrimitiveShape::kSphere, {0.35 * r.x(), 0.0, z},
                   {2.0 * (0.82 * r.x() * across + 0.003), 2.0 * (0.98 * r.y() * across + 0.003),
                    0.035 * h},
                   darker(look_.mask_colour, 0.72f), kTrunkSegments));
  }
}

// The nose from the root between the eyes (nasion) down and out to its tip, with the wings
// (alae) and nostrils beside and under the tip: what shows a face's direction in profile.
void HumanFigure::add_nose() {
  const double h = look_.head_height_m;
  const Eigen::Vector3f& skin = look_.skin;
  const Eigen::Vector3d root(face_front(0.0, kNasionShare * h) + 0.01 * h, 0.0, kNasionShare * h);
  const Eigen::Vector3d tip(face_front(0.0, kNoseTipZ * h) + kNoseTipRise * h, 0.0, kNoseTipZ * h);
  const Eigen::Vector3d along = (tip - root).normalized();
  const Eigen::Vector3d out(-along.z(), 0.0, along.x());
  // The bridge is the front of a deep ellipsoid along root to tip, which fills the nose down to the
  // face in profile. Its skin is a little lighter (1.1): the lamps' highlight on it does the rest.
  // Lighter (1.2), the bright line between the eyes kept turned heads looking frontal.
  constexpr double kBridgeDepth = 0.16;
  RenderPrimitive bridge =
      glossy(shape(PrimitiveShape::kSphere, Eigen::Vector3d::Zero(),
                   Eigen::Vector3d(kBridgeDepth * h, 0.09 * h, (tip - root).norm() + 0.03 * h),
                   lighter(skin, 1.1f), kFeatureSegments));
  bridge.X_world_shape =
      Eigen::Translation3d(0.5 * (root + tip) - 0.5 * kBridgeDepth * h * out) *
      Eigen::AngleAxisd(std::atan2(along.x(), along.z()), Eigen::Vector3d::UnitY());
  add_part(kHead, true, bridge);
  add_part(kHead, true,
           shape(PrimitiveShape::kSphere, tip - Eigen::Vector3d(0.035 * h, 0.0, 0.01 * h),
                 Eigen::Vector3d(0.08, 0.09, 0.08) * h, lighter(skin, 1.05f), kFeatureSegments));
  for (double side : {-1.0, 1.0}) {
    add_part(kHead, true,
             shape(PrimitiveShape::kSphere,
                   {tip.x() - 0.045 * h, side * kAlarShare * h, tip.z() - 0.02 * h},
                   Eigen::Vector3d(0.06, 0.055, 0.06) * h, darker(skin, 0.95f), kFeatureSegments));
    add_part(
        kHead, true,
        shape(PrimitiveShape::kSphere, {tip.x() - 0.035 * h, side * 0.025 * h, tip.z() - 0.045 * h},
              Eigen::Vector3d(0.04, 0.03, 0.015) * h, darker(skin, 0.3f), kFeatureSegments));
  }
  // The shadow under the nose, between it and the upper lip.
  add_face_feature(kHead, 0.0, -0.2 * h, Eigen::Vector3d(0.05, 0.12, 0.035) * h, 0.012 * h,
                   darker(skin, 0.45f));
}

// Lips and the dark of the mouth between them; the lower lip moves with the jaw (kJaw is the head
// frame lowered by the opening).
void HumanFigure::add_mouth() {
  const double h = look_.head_height_m;
  const Eigen::Vector3f lips = darker(look_.skin, 0.45f) + Eigen::Vector3f(0.08f, 0.0f, 0.0f);
  add_face_feature(kHead, 0.0, -0.27 * h, Eigen::Vector3d(0.08, 0.2, 0.05) * h, 0.018 * h, lips);
  add_face_feature(kHead, 0.0, -0.295 * h, Eigen::Vector3d(0.06, 0.18, 0.06) * h, 0.006 * h,
                   Eigen::Vector3f(0.12f, 0.04f, 0.04f));
  add_face_feature(kJaw, 0.0, -0.315 * h, Eigen::Vector3d(0.08, 0.19, 0.055) * h, 0.018 * h, lips);
  add_mouth_corners();
}

// Joy turns the mouth's corners up, distress down; other expressions leave them.
void HumanFigure::add_mouth_corners() {
  const double h = look_.head_height_m;
  double turn = 0.0;
  if (look_.emotion == model::Emotion::kHappy) {
    turn = kMouthCornerTurnRad;
  } else if (look_.emotion == model::Emotion::kDisturbed) {
    turn = -kMouthCornerTurnRad;
  } else {
    return;
  }
  const Eigen::Vector3f lips = darker(look_.skin, 0.45f) + Eigen::Vector3f(0.08f, 0.0f, 0.0f);
  for (double side : {-1.0, 1.0}) {
    add_face_feature(kHead, side * 0.1 * h, (turn > 0.0 ? -0.27 : -0.31) * h,
                     Eigen::Vector3d(0.06, 0.07, 0.025) * h, 0.018 * h, lips, side * turn);
  }
}

// What a camera can see of the face: the vertices of every face part (skin and features) not
// under the hair nor inside the skull and jaw, in the head frame; the jaw's twice, with the mouth
// closed and fully open.
void HumanFigure::collect_face_surface(const std::vector<Ellipsoid>& hair) {
  const double h = look_.head_height_m;
  std::set<std::array<float, 6>> seen;
  for (const Part& part : parts_) {
    if (!part.face || (part.joint != kHead && part.joint != kJaw)) {
      continue;
    }
    const RenderMesh& mesh = part.mesh;
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
      const float* v = &mesh.vertices[i * RenderMesh::kFloatsPerVertex];
      const Eigen::Vector3d point(v[0], v[1], v[2]);
      bool covered = false;
      // The hair's facets lie inside its ellipsoids, by up to 4 % with 16 segments: skin just
      // inside an ellipsoid's surface may still show between them.
      for (const auto& [centre, diameters] : hair) {
        covered = covered || ((point - centre).cwiseQuotient(0.48 * diameters)).squaredNorm() < 1.0;
      }
      // Features are set into skull, jaw and chin: what lies deeper than their skin is hidden.
      for (const auto& [centre, diameters] : skin_volumes_) {
        covered = covered || ((point - centre).cwiseQuotient(0.47 * diameters)).squaredNorm() < 1.0;
      }
      if (covered) {
        continue;
      }
      for (const double drop : {0.0, part.joint == kJaw ? kJawDropShare * h : 0.0}) {
        const std::array<float, 6> key{v[0], v[1], static_cast<float>(v[2] - drop),
                                       v[3], v[4], v[5]};
        if (seen.insert(key).second) {
          face_surface_.push_back({Eigen::Vector3d(key[0], key[1], key[2]),
                                   Eigen::Vector3d(key[3], key[4], key[5]).normalized()});
        }
      }
    }
  }
}

HumanFigure::JointFrames HumanFigure::joint_frames(const FigurePose& pose) const {
  JointFrames frames;
  const Eigen::Isometry3f body =
      translation(pose.body.position.x(), pose.body.position.y(), 0.0) *
      Eigen::Isometry3f(
          Eigen::AngleAxisf(static_cast<float>(pose.body.theta), Eigen::Vector3f::UnitZ()));
  const Eigen::Isometry3f trunk = trunk_frame(pose, body);
  frames[kPelvis] = trunk;
  const double head_turn = std::clamp(core::angle_difference(pose.head_yaw_rad, pose.body.theta),
                                      -kMaxHeadTurnRad, kMaxHeadTurnRad);
  // The neck keeps the head level however the trunk leans: people look ahead as they rise.
  frames[kHead] = trunk * translation(0.0, 0.0, head_centre_z_) *
                  rotation_y(-trunk_lean_rad(std::clamp(pose.seated, 0.0, 1.0))) *
                  Eigen::Isometry3f(
                      Eigen::AngleAxisf(static_cast<float>(head_turn), Eigen::Vector3f::UnitZ())) *
                  rotation_y(pose.head_pitch_rad);
  frames[kJaw] = frames[kHead] * translation(0.0, 0.0,
                                             -kJawDropShare * look_.head_height_m *
                                                 std::clamp(pose.mouth_open, 0.0, 1.0));
  const double amplitude = std::clamp(pose.gait_amplitude, 0.0, 1.0);
  const double seated = std::clamp(pose.seated, 0.0, 1.0);
  // Arms swing against the leg on their side; seated, the hands rest on the thighs.
  for (const double side : {1.0, -1.0}) {
    const double leg_phase = side > 0.0 ? pose.gait_phase_rad : pose.gait_phase_rad + M_PI;
    const double gesture = gesture_share(pose, side);
    const double beat = 1.0 + kBeatShare * std::clamp(pose.gesture_beat, -1.0, 1.0);
    const double arm_pitch = -amplitude * kShoulderSwingRad * std::sin(leg_phase) +
                             seated * kSeatedArmPitchRad + gesture * beat * kGestureArmPitchRad;
    const Eigen::Isometry3f shoulder =
        trunk * translation(0.0, side * shoulder_joint_y_, shoulder_z_ - 0.03 * scale_) *
        rotation_x(side * kArmAbductionRad) * rotation_y(-arm_pitch);
    const Eigen::Isometry3f elbow =
        shoulder * translation(0.0, 0.0, -upper_arm_m_) *
        rotation_y(-(0.15 + 0.3 * amplitude + seated * kSeatedElbowFlexRad +
                     gesture * beat * kGestureElbowFlexRad));
    const auto [hip, knee, ankle] = leg_frames(pose, body, side);
    frames[side > 0.0 ? kLeftHip : kRightHip] = hip;
    frames[side > 0.0 ? kLeftKnee : kRightKnee] = knee;
    frames[side > 0.0 ? kLeftAnkle : kRightAnkle] = ankle;
    frames[side > 0.0 ? kLeftShoulder : kRightShoulder] = shoulder;
    frames[side > 0.0 ? kLeftElbow : kRightElbow] = elbow;
  }
  return frames;
}

double HumanFigure::seated_hip_z(const FigurePose& pose) const {
  // The thighs rest on the seat and, when the shins are too short for them to lie flat with the
  // feet on the floor, slope down to the knees: the hips sit high enough for the thighs to clear
  // the seat's front edge, kSeatFrontM ahead of them.
  const double resting_z = pose.seat_height_m + thigh_radius_m_;
  const double slope =
      0.5 * M_PI - thigh_pitch_rad(resting_z, 0.0, world::kSeatToFeetM, kAnkleShare * scale_);
  return resting_z + kSeatFrontM * std::tan(std::max(0.0, slope));
}

double HumanFigure::thigh_pitch_rad(double hip_z, double hip_x, double ankle_x,
                                    double ankle_z) const {
  const double dx = ankle_x - hip_x, dz = ankle_z - hip_z;
  const double d = std::min(std::hypot(dx, dz), thigh_m_ + shin_m_);
  const double thigh_off = std::acos(std::clamp(
      (thigh_m_ * thigh_m_ + d * d - shin_m_ * shin_m_) / (2.0 * thigh_m_ * d), -1.0, 1.0));
  return std::atan2(dx, -dz) + thigh_off;
}

Eigen::Isometry3f HumanFigure::trunk_frame(const FigurePose& pose,
                                           const Eigen::Isometry3f& body) const {
  const double seated = std::clamp(pose.seated, 0.0, 1.0);
  if (seated <= 0.0) {
    // The trunk's parts are placed for a standing figure, over the leg it rests on.
    return body *
           translation(0.0, standing_load(pose) * kPelvisShiftM, loaded_hip_rise(pose, body));
  }
  // The hips leave the seat only once the trunk has leant forward (flexion before extension,
  // the sit-to-stand's phases; docs/cameras.md), and settle on it last when sitting down.
  const double rise = core::smoothstep((1.0 - seated - kHipsStillShare) / (1.0 - kHipsStillShare));
  const double hip_z = seated_hip_z(pose) + rise * (hip_z_ - seated_hip_z(pose));
  return body * translation(0.0, 0.0, hip_z) * rotation_y(trunk_lean_rad(seated)) *
         translation(0.0, 0.0, -hip_z_);
}

double HumanFigure::standing_load(const FigurePose& pose) const {
  return std::clamp(pose.weight_side, -1.0, 1.0) *
         (1.0 - std::clamp(pose.gait_amplitude, 0.0, 1.0)) *
         (1.0 - std::clamp(pose.seated, 0.0, 1.0));
}

double HumanFigure::loaded_hip_rise(const FigurePose& pose, const Eigen::Isometry3f& body) const {
  const double load = standing_load(pose);
  if (load == 0.0) {
    return 0.0;
  }
  FigurePose even = pose;
  even.weight_side = 0.0;
  const double side = load > 0.0 ? 1.0 : -1.0;
  const auto [hip, knee, ankle] = leg_frames(even, body, side);
  // Moved sideways over its foot, the hip rises as far as the straight leg reaches.
  const Eigen::Vector3f reach =
      body.linear().transpose() * (ankle.translation() - hip.translation()) -
      Eigen::Vector3f(0.0f, static_cast<float>(load * kPelvisShiftM), 0.0f);
  const double leg_m = thigh_m_ + shin_m_;
  const double horizontal_squared = reach.x() * reach.x() + reach.y() * reach.y();
  return std::sqrt(std::max(0.0, leg_m * leg_m - horizontal_squared)) + reach.z();
}

std::array<Eigen::Isometry3f, 3> HumanFigure::leg_frames(const FigurePose& pose,
                                                         const Eigen::Isometry3f& body,
                                                         double side) const {
  const double amplitude = std::clamp(pose.gait_amplitude, 0.0, 1.0);
  const double seated = std::clamp(pose.seated, 0.0, 1.0);
  const Eigen::Vector3f hip_point =
      trunk_frame(pose, body) *
      Eigen::Vector3f(0.0f, static_cast<float>(side * hip_joint_y_), static_cast<float>(hip_z_));
  const double load = standing_load(pose);
  if (seated > 0.0 || load != 0.0) {
    // Where the foot stands with the weight on both legs.
    FigurePose even = pose;
    even.seated = 0.0;
    even.weight_side = 0.0;
    const Eigen::Vector3f standing_ankle = leg_frames(even, body, side)[2].translation();
    if (seated > 0.0) {
      // The foot moves to the floor kSeatToFeetM ahead of the body as the figure sits.
      const Eigen::Vector3f seated_ankle =
          body * Eigen::Vector3f(static_cast<float>(world::kSeatToFeetM),
                                 static_cast<float>(side * hip_joint_y_),
                                 static_cast<float>(kAnkleShare * scale_));
      return leg_reaching(
          body, hip_point,
          standing_ankle + static_cast<float>(seated) * (seated_ankle - standing_ankle));
    }
    // Standing on one leg, the free side's hip drops.
    const bool free_leg = side * load < 0.0;
    const double drop =
        free_leg ? 2.0 * hip_joint_y_ * std::sin(std::abs(load) * kPelvisDropRad) : 0.0;
    return leg_reaching(body, hip_point - static_cast<float>(drop) * Eigen::Vector3f::UnitZ(),
                        standing_ankle);
  }
  // Standing, the feet are a little apart and the left one a little ahead (a relaxed stance);
  // the stance fades as the stride takes over.
  const double leg_phase = side > 0.0 ? pose.gait_phase_rad : pose.gait_phase_rad + M_PI;
  const double stance = 1.0 - amplitude;
  const double hip_pitch =
      amplitude * kHipSwingRad * std::sin(leg_phase) + stance * (side > 0.0 ? 0.12 : -0.06);
  const double knee_flex =
      amplitude * kKneeFlexRad * std::max(0.0, std::sin(leg_phase + 0.5 * M_PI));
  Eigen::Isometry3f hip = body;
  hip.translation() = hip_point;
  hip = hip * rotation_x(side * stance * kStanceAbductionRad) * rotation_y(-hip_pitch);
  return leg_with_flat_foot(body, hip, knee_flex);
}

std::array<Eigen::Isometry3f, 3> HumanFigure::leg_reaching(
    const Eigen::Isometry3f& body, const Eigen::Vector3f& hip_point,
    const Eigen::Vector3f& ankle_point) const {
  // Two-link reach (law of cosines) in the plane through the hip, the ankle and the body's
  // forward axis: the thigh rolls out towards the ankle and the knee bends forward.
  const Eigen::Vector3f reach = body.linear().transpose() * (ankle_point - hip_point);
  const double below = std::hypot(reach.y(), reach.z());
  const double d = std::min(static_cast<double>(reach.norm()), thigh_m_ + shin_m_);
  const double knee_inner = std::acos(std::clamp(
      (thigh_m_ * thigh_m_ + shin_m_ * shin_m_ - d * d) / (2.0 * thigh_m_ * shin_m_), -1.0, 1.0));
  Eigen::Isometry3f hip = body;
  hip.translation() = hip_point;
  hip = hip * rotation_x(std::atan2(reach.y(), -reach.z())) *
        rotation_y(-thigh_pitch_rad(0.0, 0.0, reach.x(), -below));
  return leg_with_flat_foot(body, hip, M_PI - knee_inner);
}

std::array<Eigen::Isometry3f, 3> HumanFigure::leg_with_flat_foot(const Eigen::Isometry3f& body,
                                                                 const Eigen::Isometry3f& hip,
                                                                 double knee_flex) const {
  const Eigen::Isometry3f knee = hip * translation(0.0, 0.0, -thigh_m_) * rotation_y(knee_flex);
  // The foot stays flat on its heading whatever the leg does.
  Eigen::Isometry3f ankle = body;
  ankle.translation() = (knee * translation(0.0, 0.0, -shin_m_)).translation();
  return {hip, knee, ankle};
}

void HumanFigure::append_posed(const FigurePose& pose, float body_label, float face_label,
                               RenderMesh& out) const {
  const JointFrames frames = joint_frames(pose);
  for (const Part& part : parts_) {
    append_moved(part.mesh, frames[part.joint], part.face ? face_label : body_label, out);
  }
}

// How much the arm on `side` (+1 the figure's left) gestures: the dominant one fully.
double HumanFigure::gesture_share(const FigurePose& pose, double side) const {
  const bool dominant = (side > 0.0) == look_.left_handed;
  return std::clamp(pose.gesture, 0.0, 1.0) * (dominant ? 1.0 : kOtherHandShare);
}

Eigen::Vector3d HumanFigure::hand_centre(const FigurePose& pose, bool left) const {
  const Eigen::Isometry3f& elbow = joint_frames(pose)[left ? kLeftElbow : kRightElbow];
  return (elbow * Eigen::Vector3f(0.0f, 0.0f, static_cast<float>(-forearm_m_ - 0.45 * hand_m_)))
      .cast<double>();
}

Eigen::Isometry3d HumanFigure::head_frame(const FigurePose& pose) const {
  return joint_frames(pose)[kHead].cast<double>();
}

}  // namespace ari_social_sim::rendering
