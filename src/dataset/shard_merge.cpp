#include "ari_social_sim/dataset/shard_merge.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <limits>
#include <utility>
#include <vector>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/json_string.hpp"
#include "ari_social_sim/core/text_file.hpp"

namespace ari_social_sim::dataset {
namespace {

// The lines of CocoDataset::to_json around its info and its two lists, one entry a line between.
constexpr const char* kInfoStart = "{\n\"info\": ";
constexpr const char* kImagesStart = ",\n\"images\": [\n";
constexpr const char* kAnnotationsStart = "],\n\"annotations\": [\n";
constexpr const char* kCategoriesStart = "],\n\"categories\": [\n";

using Members = std::vector<std::pair<std::string, std::string>>;

// `"key": value` as the key without its quotes and the value's text.
std::pair<std::string, std::string> member_of(const std::string& text) {
  const size_t open = text.find('"');
  const size_t close = open == std::string::npos ? open : text.find("\": ", open + 1);
  if (close == std::string::npos) {
    return {text, ""};
  }
  return {text.substr(open + 1, close - open - 1), text.substr(close + 3)};
}

// The members of a one-line JSON object as info_json prints it, `{"key": value, ...}`, the values
// as they stand (lists, objects and strings whole), so that a field compares as text.
Members members_of(const std::string& object) {
  Members members;
  if (object.size() < 2 || object.front() != '{' || object.back() != '}') {
    return members;
  }
  bool in_string = false;
  bool escaped = false;
  int depth = 0;
  size_t start = 1;
  for (size_t i = 1; i < object.size(); ++i) {
    const char c = object[i];
    if (in_string) {
      in_string = escaped || c != '"';
      escaped = !escaped && c == '\\';
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (depth > 0 && (c == ']' || c == '}')) {
      --depth;
    } else if (depth == 0 && (c == ',' || i + 1 == object.size())) {
      members.push_back(member_of(object.substr(start, i - start)));
      start = i + 1;
    }
  }
  return members;
}

// A value as a message shows it: a shard's seeds may be thousands of numbers.
std::string shortened(const std::string& value) {
  constexpr size_t kShown = 80;
  return value.size() > kShown ? value.substr(0, kShown - 3) + "..." : value;
}

// Refuses a shard's info made for another plan than `settings`', naming every field that differs:
// a shard exported with another --every, seed or scenario would merge into a file that no
// unsharded run writes. An info that differs otherwise is left to the check of the whole text.
void check_info(const std::string& info, const DatasetSettings& settings,
                const std::string& source) {
  const std::string expected = CocoDataset(settings).info_json();
  if (info == expected) {
    return;
  }
  const Members there = members_of(info);
  std::string differences;
  for (const auto& [key, value] : members_of(expected)) {
    std::string got = "nothing";
    for (const auto& [there_key, there_value] : there) {
      got = there_key == key ? there_value : got;
    }
    if (got != value) {
      differences += (differences.empty() ? "" : "; ") + key + ": expected " + shortened(value) +
                     ", got " + shortened(got);
    }
  }
  if (!differences.empty()) {
    throw core::ConfigError(source + ": info: " + differences + ": shard " +
                            settings.plan.shard_text() +
                            " was exported with other options than these (give the merge the "
                            "options the shards were exported with)");
  }
}

// The lines of text[begin, end), one JSON object each with a comma after all but the last, as
// entry lines `PREFIX{...}`.
std::string entry_lines(const std::string& text, size_t begin, size_t end, const char* prefix) {
  std::string lines;
  for (size_t at = begin; at < end;) {
    const size_t line_end = text.find('\n', at);
    const bool comma = line_end > at && text[line_end - 1] == ',';
    lines += prefix + text.substr(at, line_end - at - (comma ? 1 : 0)) + "\n";
    at = line_end + 1;
  }
  return lines;
}

// Refuses `text` unless it is `written`, showing where it first differs: the rest of that line in
// each, quoted as JSON so that a line break shows. The entries themselves are kept as they stand,
// so this checks the layout around them and the ids they start with.
void check_same_text(const std::string& written, const std::string& text,
                     const std::string& source) {
  if (text == written) {
    return;
  }
  size_t at = 0;
  while (at < text.size() && at < written.size() && text[at] == written[at]) {
    ++at;
  }
  const size_t line = 1 + static_cast<size_t>(std::count(text.begin(), text.begin() + at, '\n'));
  const size_t newline = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
  const size_t column = at - (newline == std::string::npos ? 0 : newline + 1) + 1;
  const auto rest = [at](const std::string& whole) {
    return core::json_string(whole.substr(at, std::min<size_t>(whole.find('\n', at) - at + 1, 60)));
  };
  throw core::ConfigError(source + ": line " + std::to_string(line) + ", column " +
                          std::to_string(column) + ": expected " + rest(written) + ", got " +
                          rest(text) + ": not a file export_dataset wrote, or changed since");
}

// Where shard K of N's file is in `dir`.
std::string shard_path(const std::string& dir, unsigned k, unsigned n) {
  batch::BatchPlan plan;
  plan.shard_index = k;
  plan.shard_count = n;
  return dir + "/" + annotations_file_name(plan);
}

// Refuses the merge while shard files are missing, naming the first ten: the jobs to run again.
void check_all_there(const std::string& dir, unsigned n) {
  constexpr size_t kNamed = 10;
  std::vector<std::string> missing;
  for (unsigned k = 1; k <= n; ++k) {
    const std::string path = shard_path(dir, k, n);
    if (!std::filesystem::exists(path)) {
      missing.push_back(path);
    }
  }
  if (missing.empty()) {
    return;
  }
  std::string names;
  for (size_t i = 0; i < std::min(missing.size(), kNamed); ++i) {
    names += (i > 0 ? ", " : "") + missing[i];
  }
  throw core::ConfigError(std::to_string(missing.size()) + " of " + std::to_string(n) +
                          " shard files missing: " + names +
                          (missing.size() > kNamed ? ", ..." : "") +
                          " (expected the file `export_dataset --shard K/N` writes with these "
                          "options, for K = 1.." +
                          std::to_string(n) + ")");
}

// Shard `plan`'s file at `path`, whatever its size: the merged dataset holds every line anyway.
std::string read_shard_file(const std::string& path, const batch::BatchPlan& plan) {
  const std::string what = "the COCO file of `export_dataset --shard " + plan.shard_text() + "`";
  const std::uintmax_t size =
      core::check_text_file(path, what, std::numeric_limits<std::uintmax_t>::max() - 1);
  return core::read_text_file(path, what, size);
}

}  // namespace

std::string annotations_file_name(const batch::BatchPlan& plan) {
  return "annotations" + plan.shard_suffix() + ".json";
}

DatasetSettings shard_settings(DatasetSettings whole, unsigned k, unsigned n) {
  whole.plan.shard_index = k;
  whole.plan.shard_count = n;
  return whole;
}

std::string read_entries(const std::string& text, const DatasetSettings& settings,
                         const std::string& source) {
  const size_t images = text.find(kImagesStart);
  const size_t annotations = text.find(kAnnotationsStart, images);
  const size_t categories = text.find(kCategoriesStart, annotations);
  if (text.rfind(kInfoStart, 0) != 0 || categories == std::string::npos) {
    throw core::ConfigError(source +
                            ": expected a COCO file export_dataset wrote (\"info\", then "
                            "\"images\" and \"annotations\" one a line), got other text");
  }
  check_info(text.substr(std::strlen(kInfoStart), images - std::strlen(kInfoStart)), settings,
             source);
  const std::string entries =
      entry_lines(text, images + std::strlen(kImagesStart), annotations, CocoDataset::kImageEntry) +
      entry_lines(text, annotations + std::strlen(kAnnotationsStart), categories,
                  CocoDataset::kAnnotationEntry);
  CocoDataset dataset(settings);
  dataset.add_entries(entries, source);
  check_same_text(dataset.to_json(), text, source);
  return entries;
}

CocoDataset merge_shard_files(const std::string& dir, DatasetSettings whole, unsigned shard_count) {
  whole.plan.shard_index = 1;
  whole.plan.shard_count = 1;
  check_all_there(dir, shard_count);
  CocoDataset merged(whole);
  for (unsigned k = 1; k <= shard_count; ++k) {
    const DatasetSettings shard = shard_settings(whole, k, shard_count);
    const std::string path = shard_path(dir, k, shard_count);
    merged.add_entries(read_entries(read_shard_file(path, shard.plan), shard, path), path);
  }
  merged.sort_by_id();
  return merged;
}

}  // namespace ari_social_sim::dataset
