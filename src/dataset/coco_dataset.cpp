#include "ari_social_sim/dataset/coco_dataset.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/core/json_string.hpp"

namespace ari_social_sim::dataset {
namespace {

using core::json_string;

// Four decimals (0.1 mm, 0.0001 degree, 0.1 ms) are finer than anything here is known to, and a
// fixed count makes equal values print equal bytes.
std::string fixed4(double value) {
  return core::format_text("%.4f", value);
}

std::string bool_text(bool value) {
  return value ? "true" : "false";
}

template <class T, class Format>
std::string json_list(const std::vector<T>& items, Format format) {
  std::string out = "[";
  for (size_t i = 0; i < items.size(); ++i) {
    out += (i > 0 ? ", " : "") + format(items[i]);
  }
  return out + "]";
}

std::string annotation_json(uint64_t id, uint64_t image_id, int category,
                            const rendering::PixelBox& box, const rendering::PersonLabel& label,
                            double occlusion, bool truncated, const std::string& face_fields) {
  return core::format_text(
             "{\"id\": %llu, \"image_id\": %llu, \"category_id\": %d, \"bbox\": [%d, %d, %d, %d], "
             "\"area\": %d, \"iscrowd\": 0, \"person_id\": %u, \"occlusion\": %s, "
             "\"truncated\": %s, \"distance_m\": %s",
             static_cast<unsigned long long>(id), static_cast<unsigned long long>(image_id),
             category, box.x, box.y, box.width, box.height, box.width * box.height, label.person_id,
             fixed4(occlusion).c_str(), bool_text(truncated).c_str(),
             fixed4(label.distance_m).c_str()) +
         face_fields + ", \"mask\": " + bool_text(label.mask) +
         ", \"skin_tone\": " + std::to_string(label.skin_tone) +
         ", \"seated\": " + bool_text(label.seated) + "}";
}

// The id an entry line starts with, `PREFIX{"id": N, ...`; false when it does not.
bool read_id(const std::string& line, const char* prefix, uint64_t& id) {
  const std::string start = std::string(prefix) + "{\"id\": ";
  if (line.rfind(start, 0) != 0 || line.back() != '}') {
    return false;
  }
  const char* digits = line.c_str() + start.size();
  char* end = nullptr;
  id = std::strtoull(digits, &end, 10);
  return end != digits && *end == ',';
}

// Sorts objects `{"id": N, ...}`, each with an id add or add_entries checked, by N.
void sort_objects_by_id(std::vector<std::string>& objects) {
  std::vector<std::pair<uint64_t, std::string>> keyed;
  keyed.reserve(objects.size());
  for (std::string& object : objects) {
    uint64_t id = 0;
    read_id(object, "", id);
    keyed.emplace_back(id, std::move(object));
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t i = 0; i < keyed.size(); ++i) {
    objects[i] = std::move(keyed[i].second);
  }
}

}  // namespace

uint64_t DatasetIds::image(uint64_t episode, uint64_t ordinal) {
  if (ordinal + 1 >= kImagesPerEpisode) {
    throw core::Error("episode " + std::to_string(episode) + ": more than " +
                      std::to_string(kImagesPerEpisode - 1) +
                      " images: expected fewer (use a larger --every)");
  }
  // From 1: COCO tools take id 0 for "none".
  return episode * kImagesPerEpisode + ordinal + 1;
}

uint64_t DatasetIds::annotation(uint64_t image_id, uint64_t ordinal) {
  if (ordinal + 1 >= kAnnotationsPerImage) {
    throw core::Error("image " + std::to_string(image_id) + ": more than " +
                      std::to_string(kAnnotationsPerImage - 1) + " annotations: expected fewer");
  }
  return image_id * kAnnotationsPerImage + ordinal + 1;
}

CocoDataset::CocoDataset(DatasetSettings settings) : settings_(std::move(settings)) {}

void CocoDataset::add(const DatasetImage& image,
                      const std::vector<rendering::PersonLabel>& labels) {
  if (!image_ids_.insert(image.id).second) {
    throw core::Error(image.file_name + ": image id " + std::to_string(image.id) +
                      " given twice: expected a new one");
  }
  images_.push_back(core::format_text(
      "{\"id\": %llu, \"file_name\": %s, \"width\": %d, \"height\": %d, \"camera\": %s, "
      "\"episode_seed\": %llu, \"time_s\": %s}",
      static_cast<unsigned long long>(image.id), json_string(image.file_name).c_str(), image.width,
      image.height, json_string(image.camera).c_str(),
      static_cast<unsigned long long>(image.episode_seed), fixed4(image.time_s).c_str()));
  uint64_t ordinal = 0;
  for (const rendering::PersonLabel& label : labels) {
    annotations_.push_back(annotation_json(DatasetIds::annotation(image.id, ordinal++), image.id,
                                           kPersonCategory, label.body_box, label, label.occlusion,
                                           label.truncated, ""));
    ++persons_;
    if (label.face_box) {
      // The face's own occlusion, and cut off when its box (clipped to the image) meets the
      // border.
      annotations_.push_back(annotation_json(
          DatasetIds::annotation(image.id, ordinal++), image.id, kFaceCategory, *label.face_box,
          label, label.face_occlusion, label.face_box->reaches_border(image.width, image.height),
          ", \"face_yaw_deg\": " + fixed4(label.face_yaw_deg)));
      ++faces_;
    }
  }
}

std::string CocoDataset::entries_since(const Mark& mark) const {
  std::string lines;
  for (size_t i = mark.images; i < images_.size(); ++i) {
    lines += kImageEntry + images_[i] + "\n";
  }
  for (size_t i = mark.annotations; i < annotations_.size(); ++i) {
    lines += kAnnotationEntry + annotations_[i] + "\n";
  }
  return lines;
}

void CocoDataset::add_entries(const std::string& lines, const std::string& source) {
  std::istringstream in(lines);
  size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const std::string where = source + ": line " + std::to_string(number) + " of the entries";
    uint64_t id = 0;
    if (line.rfind(kImageEntry, 0) == 0 && read_id(line, kImageEntry, id)) {
      if (!image_ids_.insert(id).second) {
        throw core::ConfigError(where + ": image id " + std::to_string(id) +
                                " given twice: expected a new one");
      }
      images_.push_back(line.substr(std::strlen(kImageEntry)));
    } else if (line.rfind(kAnnotationEntry, 0) == 0 && read_id(line, kAnnotationEntry, id)) {
      annotations_.push_back(line.substr(std::strlen(kAnnotationEntry)));
      const bool face =
          line.find(core::format_text("\"category_id\": %d,", kFaceCategory)) != std::string::npos;
      ++(face ? faces_ : persons_);
    } else {
      throw core::ConfigError(where +
                              ": expected `image {\"id\": ...}` or `annotation {\"id\": "
                              "...}`, got '" +
                              line.substr(0, 40) + "'");
    }
  }
}

void CocoDataset::sort_by_id() {
  sort_objects_by_id(images_);
  sort_objects_by_id(annotations_);
}

std::string CocoDataset::to_json() const {
  std::string out = "{\n\"info\": " + info_json() + ",\n";
  const auto lines = [](const std::vector<std::string>& objects) {
    std::string text;
    for (size_t i = 0; i < objects.size(); ++i) {
      text += objects[i] + (i + 1 < objects.size() ? ",\n" : "\n");
    }
    return text;
  };
  out += "\"images\": [\n" + lines(images_) + "],\n";
  out += "\"annotations\": [\n" + lines(annotations_) + "],\n";
  out += core::format_text(
      "\"categories\": [\n"
      "{\"id\": %d, \"name\": \"person\", \"supercategory\": \"person\"},\n"
      "{\"id\": %d, \"name\": \"face\", \"supercategory\": \"person\"}\n"
      "]\n}\n",
      kPersonCategory, kFaceCategory);
  return out;
}

std::string CocoDataset::info_json() const {
  const DatasetSettings& s = settings_;
  std::vector<uint64_t> seeds;
  for (uint64_t episode : s.plan.episode_indices()) {
    seeds.push_back(s.plan.seed_of(episode));
  }
  std::string rates = "{";
  for (size_t i = 0; i < s.cameras.size(); ++i) {
    rates += (i > 0 ? ", " : "") + json_string(s.cameras[i]) + ": " + fixed4(s.frame_rate_hz[i]);
  }
  rates += "}";
  return "{\"description\": " +
         json_string("ari_social_sim export_dataset: scenario " + s.scenario +
                     ", ARI's cameras with people labels") +
         ", \"scenario\": " + json_string(s.scenario) +
         ", \"episodes\": " + std::to_string(s.plan.episodes) +
         ", \"first_seed\": " + std::to_string(s.plan.first_seed) +
         ", \"shard\": " + json_string(s.plan.shard_text()) +
         ", \"seeds\": " + json_list(seeds, [](uint64_t seed) { return std::to_string(seed); }) +
         ", \"cameras\": " + json_list(s.cameras, json_string) +
         ", \"every_s\": " + (s.every_s ? fixed4(*s.every_s) : "null") +
         ", \"motion_blur\": " + (s.motion_blur ? "true" : "false") +
         ", \"frame_rate_hz\": " + rates + "}";
}

}  // namespace ari_social_sim::dataset
