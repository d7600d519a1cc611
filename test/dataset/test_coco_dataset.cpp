// The COCO file export_dataset writes: its layout, ids, escaping and fixed number formatting.
#include <gtest/gtest.h>

#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dataset/coco_dataset.hpp"

namespace ari_social_sim::dataset {
namespace {

DatasetSettings two_cameras() {
  DatasetSettings settings;
  settings.scenario = "join_group";
  settings.plan.episodes = 3;
  settings.plan.first_seed = 7;
  settings.plan.shard_index = 2;
  settings.plan.shard_count = 2;
  settings.cameras = {"head_front_camera", "torso_front_camera"};
  settings.frame_rate_hz = {0.5, 0.5};
  settings.every_s = 2.0;
  return settings;
}

rendering::PersonLabel facing_person() {
  rendering::PersonLabel label;
  label.person_id = 10;
  label.body_box = {100, 50, 40, 120};
  label.occlusion = 0.125;
  label.face_box = rendering::PixelBox{110, 50, 12, 15};
  label.face_occlusion = 0.0;
  label.face_yaw_deg = 12.34567;
  label.distance_m = 2.5;
  label.mask = true;
  label.skin_tone = 6;
  return label;
}

TEST(CocoDataset, WritesInfoImagesAnnotationsAndCategoriesWithFixedDecimals) {
  CocoDataset dataset(two_cameras());
  DatasetImage image;
  image.id = DatasetIds::image(1, 0);
  image.file_name = "images/head_front_camera/join_group_8_000000.png";
  image.width = 1280;
  image.height = 960;
  image.camera = "head_front_camera";
  image.episode_seed = 8;
  image.time_s = 0.1;
  rendering::PersonLabel back_turned;
  back_turned.person_id = 11;
  back_turned.body_box = {0, 10, 20, 30};
  back_turned.truncated = true;
  dataset.add(image, {facing_person(), back_turned});
  EXPECT_EQ(dataset.image_count(), 1u);
  EXPECT_EQ(dataset.annotation_count(), 3u);
  EXPECT_EQ(dataset.count(CocoDataset::kPersonCategory), 2u);
  EXPECT_EQ(dataset.count(CocoDataset::kFaceCategory), 1u);

  const std::string json = dataset.to_json();
  // Shard 2 of 2 of episodes 0..2 holds episode 1 only: seed 8.
  EXPECT_NE(json.find("\"episodes\": 3, \"first_seed\": 7, \"shard\": \"2/2\", \"seeds\": [8]"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"every_s\": 2.0000, \"motion_blur\": false, "
                      "\"frame_rate_hz\": {\"head_front_camera\": 0.5000, "
                      "\"torso_front_camera\": 0.5000}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("{\"id\": 1000001, \"file_name\": "
                      "\"images/head_front_camera/join_group_8_000000.png\", \"width\": 1280, "
                      "\"height\": 960, \"camera\": \"head_front_camera\", \"episode_seed\": 8, "
                      "\"time_s\": 0.1000}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("{\"id\": 1000001001, \"image_id\": 1000001, \"category_id\": 1, \"bbox\": "
                      "[100, 50, 40, 120], \"area\": 4800, \"iscrowd\": 0, \"person_id\": 10, "
                      "\"occlusion\": 0.1250, \"truncated\": false, \"distance_m\": 2.5000, "
                      "\"mask\": true, \"skin_tone\": 6, \"seated\": false}"),
            std::string::npos)
      << json;
  // The face: its own occlusion, inside the image (not cut off), and its yaw.
  EXPECT_NE(json.find("{\"id\": 1000001002, \"image_id\": 1000001, \"category_id\": 2, \"bbox\": "
                      "[110, 50, 12, 15], \"area\": 180, \"iscrowd\": 0, \"person_id\": 10, "
                      "\"occlusion\": 0.0000, \"truncated\": false, \"distance_m\": 2.5000, "
                      "\"face_yaw_deg\": 12.3457, \"mask\": true, \"skin_tone\": 6, "
                      "\"seated\": false}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("{\"id\": 1000001003, \"image_id\": 1000001, \"category_id\": 1, \"bbox\": "
                      "[0, 10, 20, 30]"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("{\"id\": 2, \"name\": \"face\", \"supercategory\": \"person\"}"),
            std::string::npos);
  EXPECT_EQ(json.front(), '{');
  EXPECT_EQ(json.substr(json.size() - 4), "]\n}\n");
}

TEST(CocoDataset, EscapesNamesAndRefusesAnImageIdTwice) {
  DatasetSettings settings = two_cameras();
  settings.scenario = "a \"quoted\" name";
  settings.every_s.reset();
  CocoDataset dataset(settings);
  EXPECT_NE(dataset.to_json().find("\"scenario\": \"a \\\"quoted\\\" name\""), std::string::npos);
  EXPECT_NE(dataset.to_json().find("\"every_s\": null"), std::string::npos);
  DatasetImage image;
  image.id = 5;
  dataset.add(image, {});
  EXPECT_THROW(dataset.add(image, {}), core::Error);
}

TEST(DatasetIds, DependOnTheEpisodeAndOrdinalOnlyAndStayBelowTwoToThe53) {
  EXPECT_EQ(DatasetIds::image(0, 0), 1u);
  EXPECT_EQ(DatasetIds::image(3, 4), 3000005u);
  EXPECT_EQ(DatasetIds::annotation(3000005, 0), 3000005001u);
  EXPECT_THROW(DatasetIds::image(0, DatasetIds::kImagesPerEpisode - 1), core::Error);
  EXPECT_THROW(DatasetIds::annotation(1, DatasetIds::kAnnotationsPerImage - 1), core::Error);
  // The largest ids of a million-episode batch: JSON readers hold them exactly as doubles.
  const uint64_t last_image = DatasetIds::image(999999, DatasetIds::kImagesPerEpisode - 2);
  EXPECT_LT(DatasetIds::annotation(last_image, DatasetIds::kAnnotationsPerImage - 2),
            uint64_t{1} << 53);
}

}  // namespace
}  // namespace ari_social_sim::dataset
