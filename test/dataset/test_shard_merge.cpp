// The COCO files of a plan's shards merged into the unsharded file, and the shard files refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dataset/shard_merge.hpp"

namespace ari_social_sim::dataset {
namespace {

namespace fs = std::filesystem;

// Five episodes of one camera, a frame every 2 s.
DatasetSettings whole_plan() {
  DatasetSettings settings;
  settings.scenario = "join_group";
  settings.plan.episodes = 5;
  settings.plan.first_seed = 7;
  settings.cameras = {"torso_front_camera"};
  settings.frame_rate_hz = {0.5};
  settings.every_s = 2.0;
  return settings;
}

// Episode `episode`'s images as export_dataset adds them: two, the second with a person and a
// face.
void add_episode(CocoDataset& dataset, uint64_t episode) {
  for (uint64_t ordinal = 0; ordinal < 2; ++ordinal) {
    DatasetImage image;
    image.id = DatasetIds::image(episode, ordinal);
    image.file_name = "images/torso_front_camera/join_group_" + std::to_string(7 + episode) +
                      "_00000" + std::to_string(ordinal) + ".png";
    image.width = 848;
    image.height = 480;
    image.camera = "torso_front_camera";
    image.episode_seed = 7 + episode;
    image.time_s = 2.0 * static_cast<double>(ordinal);
    rendering::PersonLabel label;
    label.person_id = static_cast<unsigned>(10 + episode);
    label.body_box = {100, 50, 40, 120};
    label.face_box = rendering::PixelBox{110, 50, 12, 15};
    dataset.add(image, ordinal == 0 ? std::vector<rendering::PersonLabel>{}
                                    : std::vector<rendering::PersonLabel>{label});
  }
}

// The file one process writes for `settings`' shard.
std::string export_text(const DatasetSettings& settings) {
  CocoDataset dataset(settings);
  for (uint64_t episode : settings.plan.episode_indices()) {
    add_episode(dataset, episode);
  }
  return dataset.to_json();
}

// A fresh folder holding the files of shards 1/N..N/N of whole_plan(), but shard `left_out`.
std::string shards_folder(const std::string& name, unsigned shards, unsigned left_out = 0) {
  const std::string dir = ::testing::TempDir() + name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (unsigned k = 1; k <= shards; ++k) {
    const DatasetSettings shard = shard_settings(whole_plan(), k, shards);
    if (k != left_out) {
      std::ofstream(dir + "/" + annotations_file_name(shard.plan)) << export_text(shard);
    }
  }
  return dir;
}

// The message of the core::ConfigError that `action` throws, or "" when it throws none.
template <class Action>
std::string refusal(Action action) {
  try {
    action();
  } catch (const core::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ShardMerge, NamesTheFilesAsExportDatasetWritesThem) {
  batch::BatchPlan plan;
  EXPECT_EQ(annotations_file_name(plan), "annotations.json");
  plan.shard_index = 2;
  plan.shard_count = 3;
  EXPECT_EQ(annotations_file_name(plan), "annotations_shard2-of-3.json");
}

TEST(ShardMerge, ShardsMergeIntoTheUnshardedFileByteForByte) {
  const std::string whole = export_text(whole_plan());
  // Three shards of five episodes: 0 and 3, 1 and 4, 2; more shards than episodes leave some
  // empty.
  for (unsigned shards : {3u, 7u}) {
    const std::string dir = shards_folder("shard_merge_" + std::to_string(shards), shards);
    const CocoDataset merged = merge_shard_files(dir, whole_plan(), shards);
    EXPECT_EQ(merged.to_json(), whole) << shards << " shards";
    EXPECT_EQ(merged.image_count(), 10u);
    EXPECT_EQ(merged.count(CocoDataset::kFaceCategory), 5u);
  }
}

TEST(ShardMerge, ReadsBackWhatToJsonWroteAndRefusesAnyOtherText) {
  const DatasetSettings shard = shard_settings(whole_plan(), 2, 3);
  const std::string text = export_text(shard);
  CocoDataset again(shard);
  again.add_entries(read_entries(text, shard, "shard.json"), "shard.json");
  EXPECT_EQ(again.to_json(), text);

  DatasetSettings other_every = shard;
  other_every.every_s = 1.0;
  other_every.frame_rate_hz = {1.0};
  EXPECT_EQ(refusal([&] { read_entries(export_text(other_every), shard, "shard.json"); }),
            "shard.json: info: every_s: expected 2.0000, got 1.0000; frame_rate_hz: expected "
            "{\"torso_front_camera\": 0.5000}, got {\"torso_front_camera\": 1.0000}: shard 2/3 was "
            "exported with other options than these (give the merge the options the shards were "
            "exported with)");
  // Long values, the seeds of many episodes, are cut short in the message.
  DatasetSettings other_episodes = shard;
  other_episodes.plan.episodes = 100;
  const std::string many = refusal([&] { read_entries(export_text(other_episodes), shard, "s"); });
  EXPECT_NE(
      many.find("s: info: episodes: expected 5, got 100; seeds: expected [8, 11], got [8, 11, "
                "14, 17, "),
      std::string::npos)
      << many;
  EXPECT_NE(many.find("...: shard 2/3 was exported with other options"), std::string::npos) << many;
  EXPECT_LT(many.size(), 300u) << many;

  // The layout changed (a comma dropped), or an entry that does not start with its id: refused
  // where it first differs. An entry's other fields are kept as they stand.
  std::string edited = text;
  edited.erase(edited.find("},\n{\"id\"") + 1, 1);
  const std::string changed = refusal([&] { read_entries(edited, shard, "shard.json"); });
  EXPECT_NE(changed.find("shard.json: line 4, column "), std::string::npos) << changed;
  EXPECT_NE(changed.find(": expected \",\\n\", got \"\\n\": not a file export_dataset wrote"),
            std::string::npos)
      << changed;
  edited = text;
  edited.replace(edited.find("{\"id\": 1000002001"), 7, "{\"no\": ");
  const std::string no_id = refusal([&] { read_entries(edited, shard, "shard.json"); });
  EXPECT_NE(no_id.find("shard.json: line 5 of the entries: expected `image {\"id\": ...}`"),
            std::string::npos)
      << no_id;
  const std::string other = refusal([&] { read_entries("{\"images\": []}", shard, "shard.json"); });
  EXPECT_EQ(other.rfind("shard.json: expected a COCO file export_dataset wrote", 0), 0u) << other;
}

TEST(ShardMerge, RefusesMissingShardsNamingThem) {
  const std::string dir = shards_folder("shard_merge_missing", 3, 2);
  EXPECT_EQ(refusal([&] { merge_shard_files(dir, whole_plan(), 3); }),
            "1 of 3 shard files missing: " + dir +
                "/annotations_shard2-of-3.json (expected the file `export_dataset --shard K/N` "
                "writes with these options, for K = 1..3)");
  const std::string message = refusal([&] { merge_shard_files(dir, whole_plan(), 12); });
  EXPECT_EQ(
      message.rfind("12 of 12 shard files missing: " + dir + "/annotations_shard1-of-12.json, ", 0),
      0u)
      << message;
  EXPECT_NE(message.find("annotations_shard10-of-12.json, ... (expected"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace ari_social_sim::dataset
