#pragma once

// ARI v1's sensor geometry: where the cameras and the microphone array are mounted and what the
// cameras see. The one source of these facts for the physics (rendering, physics/ari_cameras.cpp)
// and the perception (fields of view, perception/perception_config.hpp), so that the images and
// the simulated detections agree. Mounts are ari_robot's URDF (urdf/ari.urdf, docs/references.md
// #ari_robot); lengths in metres, angles in degrees. docs/cameras.md lists the choices made where
// PAL's Gazebo model of ARI differs from the real robot.

namespace ari_social_sim::model {

/// A point in a parent frame (x forward, y left, z up unless the frame says otherwise).
struct MountPoint {
  double x_m{0.0};
  double y_m{0.0};
  double z_m{0.0};
};

/// A camera's image and lens.
struct CameraGeometry {
  int width_px{0};
  int height_px{0};
  double hfov_deg{0.0};  // horizontal field of view across the full width
};

// The head: base_footprint -> base_link (z 0.125) -> head_1_joint (pan) -> head_2_joint (tilt)
// -> head_front_camera. head_2_link's z points to the robot's right at tilt 0.
inline constexpr double kBaseLinkHeightM = 0.125;
inline constexpr MountPoint kHeadPanJointInBaseLink{-0.2255, 0.0, 1.1915};
inline constexpr MountPoint kHeadTiltJointInPanLink{0.0425, 0.0, 0.093};
inline constexpr MountPoint kHeadCameraInTiltLink{0.0634, 0.182, 0.0};

/// The head camera is a Raspberry Pi Camera Module v2 (Sony IMX219, 3.04 mm lens): 62.2 degrees
/// horizontally (Raspberry Pi camera hardware documentation, docs/references.md
/// #raspberry-pi-camera-module-v2). D6.4 §3.5.3 rounds it to 62 degrees; PAL's Gazebo model uses
/// 80. The 1280 x 960 image is the Gazebo model's (4:3, the sensor's aspect).
inline constexpr CameraGeometry kHeadCamera{1280, 960, 62.2};

/// The head camera ahead of the pan axis (head level, pan 0): what a planar model of the head
/// needs.
constexpr double head_camera_ahead_of_pan_axis_m() {
  return kHeadTiltJointInPanLink.x_m + kHeadCameraInTiltLink.x_m;
}

/// The head camera's height above the floor with the head level (head_2_link's y is up then).
constexpr double head_camera_height_m() {
  return kBaseLinkHeightM + kHeadPanJointInBaseLink.z_m + kHeadTiltJointInPanLink.z_m +
         kHeadCameraInTiltLink.y_m;
}

/// Torso front fisheye (ELP IMX179; D6.4 §3.5.2, 180 degrees), pitched up, in base_footprint. It
/// is the camera perception tracks bodies with. 1280 x 960 is the Gazebo model's image; the real
/// ELP streams 3264 x 2448 MJPEG.
inline constexpr MountPoint kFrontFisheyeInFootprint{-0.142, 0.0, 1.321};
inline constexpr double kFrontFisheyePitchUpDeg = 19.0;
inline constexpr CameraGeometry kFisheyeCamera{1280, 960, 180.0};

/// Rear fisheye, facing backwards and pitched up, in base_footprint (the same ELP camera).
inline constexpr MountPoint kRearFisheyeInFootprint{-0.321, 0.0, 1.288};
inline constexpr double kRearFisheyePitchUpDeg = 25.0;

/// Torso D435: the colour optical frame (0.015 m left of the depth frame), pitched down, in
/// base_footprint; its colour sensor's lens and depth range.
inline constexpr MountPoint kTorsoCameraInFootprint{-0.104, 0.033, 1.105};
inline constexpr double kTorsoCameraPitchDownDeg = 42.5;
inline constexpr CameraGeometry kTorsoCamera{848, 480, 69.4};
inline constexpr double kTorsoCameraMinRangeM = 0.2;
inline constexpr double kTorsoCameraMaxRangeM = 10.0;

/// T265 behind the torso, facing backwards and pitched down: its pose frame in base_footprint and
/// its two fisheyes 64 mm apart across it.
inline constexpr MountPoint kBackCameraInFootprint{-0.328, 0.009, 1.159};
inline constexpr double kBackCameraPitchDownDeg = 15.0;
inline constexpr double kBackCameraBaselineM = 0.064;
inline constexpr CameraGeometry kBackFisheyeCamera{848, 800, 163.0};

/// ReSpeaker array in the torso (torso_mic_front_link), in base_footprint.
inline constexpr MountPoint kMicrophoneInFootprint{-0.122, 0.0, kBaseLinkHeightM + 0.803};

/// The ReSpeaker Mic Array v2.0's four microphones in its own frame (torso_mic_front_link): on a
/// circle of 32 mm radius, at 90 degree steps, in the order of its raw channels 1-4 (ODAS's
/// configuration of the array, docs/references.md#respeaker-mic-array-v20). Which way the board
/// faces in ARI's torso is not published: microphone 3 (channel 3) is taken to face forward.
inline constexpr MountPoint kArrayMicrophones[4] = {
    {-0.032, 0.0, 0.0}, {0.0, -0.032, 0.0}, {0.032, 0.0, 0.0}, {0.0, 0.032, 0.0}};
/// Its sample rate and channels (6-channel firmware: 0 processed, 1-4 raw, 5 playback).
inline constexpr int kArraySampleRateHz = 16000;
inline constexpr int kArrayChannels = 6;

}  // namespace ari_social_sim::model
