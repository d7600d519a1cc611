#pragma once

#include <string>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::rendering {

/// What a real camera does to the light the renderer computes (docs/cameras.md, "Camera
/// effects"): every camera of a rig gets them, each switchable, the random ones seeded. The
/// defaults model the head camera's small-pixel sensor (the Raspberry Pi Camera v2's IMX219)
/// behind an image processor that has corrected most of its lens shading.
struct CameraEffects {
  bool enabled{true};
  int antialiasing_samples{1};       // samples per pixel (multisampling); 1 draws pixel centres
  double optical_blur_px{0.6};       // the lens's and the optical low-pass filter's blur (std)
  double corner_illumination{0.8};   // vignetting: light in the corners against the centre
  bool auto_exposure{true};          // steer the frame's mean brightness to exposure_target
  double exposure_target{0.18};      // mean linear luminance (18 % grey, as light meters aim)
  double max_gain{8.0};              // auto exposure's highest gain: darker scenes stay dark
  double white_balance_error{0.03};  // automatic white balance's error per channel (std)
  bool bayer{true};                  // a Bayer sensor and the image processor's demosaicing
  double full_well_electrons{4300};  // electrons a pixel holds at white: shot noise
  double read_noise_electrons{3.0};  // the read-out's noise (std), electrons
  bool motion_blur{false};           // smear what moves while the shutter is open
  double longest_exposure_s{0.033};  // auto exposure's longest: a 30 fps sensor mode's frame

  template <class V>
  void visit(V& v) {
    v.field("enabled", enabled, "apply the effects below (false: the renderer's image as drawn)");
    v.field(
        "antialiasing_samples", antialiasing_samples,
        "samples per pixel (multisampling); 1 draws each pixel from its centre. Cheap on a GPU; "
        "on llvmpipe (the CPU) 4 samples cost several times a frame (docs/PERFORMANCE.md)");
    v.rule("antialiasing_samples",
           antialiasing_samples == 1 || antialiasing_samples == 2 || antialiasing_samples == 4 ||
               antialiasing_samples == 8,
           "1, 2, 4 or 8", std::to_string(antialiasing_samples));
    v.field("optical_blur_px", optical_blur_px,
            "standard deviation of the optics' blur (lens and optical low-pass filter), pixels; "
            "it softens drawn edges as a camera's optics do; 0 for none",
            core::between(0.0, 5.0));
    v.field("corner_illumination", corner_illumination,
            "light reaching the image corners against the centre (1: no vignetting)",
            core::between(0.1, 1.0));
    v.field("auto_exposure", auto_exposure,
            "scale each frame's exposure so that its mean brightness is exposure_target");
    v.field("exposure_target", exposure_target, "mean linear luminance, 0-1",
            core::between(0.01, 0.9));
    v.field("max_gain", max_gain, "highest exposure gain auto exposure may use",
            core::between(1.0, 64.0));
    v.field("white_balance_error", white_balance_error,
            "standard deviation of the white balance's error per colour channel (fraction)",
            core::between(0.0, 0.3));
    v.field("bayer", bayer,
            "sample one colour per pixel (BGGR) and demosaic, as a colour sensor does");
    v.field("full_well_electrons", full_well_electrons,
            "electrons per pixel at white: photon shot noise is their square root",
            core::between(100.0, 1e6));
    v.field("read_noise_electrons", read_noise_electrons,
            "standard deviation of the read-out noise, electrons", core::between(0.0, 1000.0));
    v.field("motion_blur", motion_blur,
            "smear people and the background along their motion in the image while the shutter "
            "is open (auto exposure's time, at most longest_exposure_s); pinhole cameras, from "
            "their second frame. Off by default: it costs frame time (docs/PERFORMANCE.md)");
    v.field("longest_exposure_s", longest_exposure_s,
            "the exposure time of a frame at the renderer's brightness, the longest auto exposure "
            "uses (it shortens it for brighter scenes), seconds",
            core::between(0.0001, 0.5));
  }
};

}  // namespace ari_social_sim::rendering
