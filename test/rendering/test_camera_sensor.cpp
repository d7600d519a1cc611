// rendering::CameraSensor: what the head camera's sensor and image processor do to the rendered
// light, checked against the model's own arithmetic.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/rendering/camera_sensor.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kFov = 62.2 * M_PI / 180.0;  // the head camera's

double linear(double display) {
  return std::pow(display / 255.0, 2.2);
}

// Effects that change nothing but what a test looks at.
CameraEffects only(void (*set)(CameraEffects&)) {
  CameraEffects effects;
  effects.corner_illumination = 1.0;
  effects.auto_exposure = false;
  effects.white_balance_error = 0.0;
  effects.bayer = false;
  effects.read_noise_electrons = 0.0;
  effects.full_well_electrons = 1e6;
  effects.optical_blur_px = 0.0;
  set(effects);
  return effects;
}

cv::Mat flat(const cv::Vec3b& colour) {
  return cv::Mat(kHeight, kWidth, CV_8UC3, cv::Scalar(colour[0], colour[1], colour[2]));
}

TEST(CameraSensor, ShotNoiseIsWhatItsElectronsGive) {
  // 4500 electrons at white, mid grey (display 128): sigma = sqrt(light / 4500) in linear light,
  // times the output gamma's slope in display levels.
  CameraSensor sensor(only([](CameraEffects& e) { e.full_well_electrons = 4500; }), kWidth, kHeight,
                      kFov, 1, 0);
  cv::Mat image = flat({128, 128, 128});
  sensor.expose(image);
  cv::Scalar mean, stddev;
  cv::meanStdDev(image.reshape(1), mean, stddev);
  const double light = linear(128);
  const double slope = 255.0 / 2.2 * std::pow(light, 1.0 / 2.2 - 1.0);
  const double expected = std::sqrt(light / 4500) * slope;  // 2.0 levels
  EXPECT_NEAR(stddev[0], expected, 0.05 * expected);
  EXPECT_NEAR(mean[0], 128.0, 0.2);
}

TEST(CameraSensor, TheSameSeedGivesTheSameFramesAndAnotherOtherOnes) {
  const CameraEffects effects;  // every effect on
  CameraSensor a(effects, kWidth, kHeight, kFov, 7, 0);
  CameraSensor b(effects, kWidth, kHeight, kFov, 7, 0);
  CameraSensor other_seed(effects, kWidth, kHeight, kFov, 8, 0);
  CameraSensor other_camera(effects, kWidth, kHeight, kFov, 7, 1);
  for (int frame = 0; frame < 2; ++frame) {
    cv::Mat images[4];
    CameraSensor* sensors[4] = {&a, &b, &other_seed, &other_camera};
    for (int k = 0; k < 4; ++k) {
      images[k] = flat({90, 120, 150});
      sensors[k]->expose(images[k]);
    }
    EXPECT_EQ(cv::norm(images[0], images[1], cv::NORM_INF), 0.0) << "frame " << frame;
    EXPECT_GT(cv::norm(images[0], images[2], cv::NORM_L1), 0.0);
    EXPECT_GT(cv::norm(images[0], images[3], cv::NORM_L1), 0.0);
  }
}

TEST(CameraSensor, CornersGetTheirShareOfTheLight) {
  CameraSensor sensor(only([](CameraEffects& e) { e.corner_illumination = 0.6; }), kWidth, kHeight,
                      kFov, 1, 0);
  cv::Mat image = flat({200, 200, 200});
  sensor.expose(image);
  const double centre = linear(image.at<cv::Vec3b>(kHeight / 2, kWidth / 2)[1]);
  const double corner = linear(image.at<cv::Vec3b>(0, 0)[1]);
  EXPECT_NEAR(corner / centre, 0.6, 0.01);
}

TEST(CameraSensor, AutoExposureBringsTheMeanToItsTarget) {
  for (const int grey : {70, 230}) {  // gains 3.1 and 0.27
    CameraSensor sensor(only([](CameraEffects& e) { e.auto_exposure = true; }), kWidth, kHeight,
                        kFov, 1, 0);
    cv::Mat image =
        flat({static_cast<uint8_t>(grey), static_cast<uint8_t>(grey), static_cast<uint8_t>(grey)});
    sensor.expose(image);
    EXPECT_NEAR(sensor.last_gain(), 0.18 / linear(grey), 1e-6) << grey;
    EXPECT_NEAR(linear(cv::mean(image)[0]), 0.18, 0.004) << grey;
  }
}

TEST(CameraSensor, DemosaicingKeepsFlatColours) {
  CameraSensor sensor(only([](CameraEffects& e) { e.bayer = true; }), kWidth, kHeight, kFov, 1, 0);
  for (const cv::Vec3b& colour : {cv::Vec3b(220, 40, 30), cv::Vec3b(30, 200, 60),
                                  cv::Vec3b(20, 50, 210), cv::Vec3b(180, 140, 110)}) {
    cv::Mat image = flat(colour);
    sensor.expose(image);
    const cv::Vec3b middle = image.at<cv::Vec3b>(kHeight / 2, kWidth / 2);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(middle[c], colour[c], 1) << "channel " << c << " of " << colour;
    }
  }
}

TEST(CameraSensor, BadEffectsAreNamed) {
  CameraEffects effects;
  effects.antialiasing_samples = 3;
  try {
    core::check_fields(effects, "effects");
    FAIL() << "3 samples accepted";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("antialiasing_samples: expected 1, 2, 4 or 8, got 3"),
              std::string::npos)
        << e.what();
  }
}

// Motion blur's exposure time must be a time a shutter can stay open.
TEST(CameraSensor, ABadLongestExposureIsNamed) {
  CameraEffects effects;
  effects.motion_blur = true;
  effects.longest_exposure_s = 0.0;
  try {
    core::check_fields(effects, "effects");
    FAIL() << "an exposure of 0 s accepted";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(
        std::string(e.what()).find("longest_exposure_s: expected a number [0.0001, 0.5], got 0"),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ari_social_sim::rendering
