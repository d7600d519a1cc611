#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "ari_social_sim/rendering/image_labels.hpp"

namespace ari_social_sim::dataset {

/// How a labelled dataset was made: what export_dataset writes under the COCO file's "info".
struct DatasetSettings {
  std::string scenario;               // its name
  batch::BatchPlan plan;              // episodes, first seed and shard
  std::vector<std::string> cameras;   // CameraSpec::name of each camera exported
  std::vector<double> frame_rate_hz;  // each camera's frames per second of sim time
  std::optional<double> every_s;      // --every; unset: each camera's own rate
  bool motion_blur{false};            // --motion-blur
};

/// One image of the dataset, with the fields COCO leaves to the producer: the camera, the episode
/// and the instant.
struct DatasetImage {
  uint64_t id{0};         // DatasetIds::image
  std::string file_name;  // relative to the dataset's folder
  int width{0};
  int height{0};
  std::string camera;
  uint64_t episode_seed{0};
  double time_s{0.0};
};

/// Image and annotation ids that depend only on the image's place in the whole batch (episode,
/// then its images in the order they were taken), never on the shard that made it: the files of
/// the shards of one batch merge without renumbering, and hold the ids the unsharded run would.
struct DatasetIds {
  static constexpr uint64_t kImagesPerEpisode = 1000000;
  static constexpr uint64_t kAnnotationsPerImage = 1000;

  /// Image `ordinal` (from 0) of episode `episode`, from 1 (COCO tools read 0 as none). Throws
  /// core::Error when the episode has more than kImagesPerEpisode - 1 images.
  static uint64_t image(uint64_t episode, uint64_t ordinal);
  /// Annotation `ordinal` (from 0) of an image, from 1. Throws core::Error when the image has more
  /// than kAnnotationsPerImage - 1 annotations.
  static uint64_t annotation(uint64_t image_id, uint64_t ordinal);
};

/// Labelled images as one COCO object-detection file: categories person (1) and face (2, its
/// supercategory person); one person annotation per labelled person (body box) and one face
/// annotation per face box. Each annotation carries the label's extra fields (person_id,
/// occlusion, truncated, distance_m, mask; face_yaw_deg on faces). The text has no timestamp and
/// prints numbers with fixed decimals, so the same images give the same bytes.
class CocoDataset {
 public:
  static constexpr int kPersonCategory = 1;
  static constexpr int kFaceCategory = 2;
  /// What each line of entries_since starts with, before the image's or annotation's object.
  static constexpr const char* kImageEntry = "image ";
  static constexpr const char* kAnnotationEntry = "annotation ";

  explicit CocoDataset(DatasetSettings settings);

  /// Adds an image and its labels' annotations. The image's id must be new (core::Error
  /// otherwise).
  void add(const DatasetImage& image, const std::vector<rendering::PersonLabel>& labels);

  size_t image_count() const { return images_.size(); }
  size_t annotation_count() const { return annotations_.size(); }
  size_t count(int category) const { return category == kPersonCategory ? persons_ : faces_; }

  /// The whole file: "info", "images", "annotations", "categories"; one image or annotation per
  /// line.
  std::string to_json() const;
  /// The "info" object of to_json, on one line: what the dataset was made with.
  std::string info_json() const;

  /// How many images and annotations the dataset holds, to take entries_since from.
  struct Mark {
    size_t images{0};
    size_t annotations{0};
  };
  Mark mark() const { return {images_.size(), annotations_.size()}; }
  /// The images and annotations added since `mark`, one a line (`image {...}`, `annotation
  /// {...}`), exactly as to_json prints them: what export_dataset keeps of each finished episode
  /// so that a resumed run writes the bytes an uninterrupted one would.
  std::string entries_since(const Mark& mark) const;
  /// Adds entries_since's lines back. Throws core::ConfigError naming `source` for a line of
  /// another form, or an image id given twice.
  void add_entries(const std::string& lines, const std::string& source);
  /// Puts the images and the annotations in id order: the order of the whole batch, episode by
  /// episode, whatever order the entries came in (the shards' entries, merge_shard_files).
  void sort_by_id();

 private:
  DatasetSettings settings_;
  std::set<uint64_t> image_ids_;
  std::vector<std::string> images_;       // JSON objects
  std::vector<std::string> annotations_;  // JSON objects
  size_t persons_{0};
  size_t faces_{0};
};

}  // namespace ari_social_sim::dataset
