#pragma once

#include <string>

#include "ari_social_sim/batch/batch_plan.hpp"
#include "ari_social_sim/dataset/coco_dataset.hpp"

namespace ari_social_sim::dataset {

/// The COCO file export_dataset writes for `plan` in its folder: `annotations.json`, or
/// `annotations_shardK-of-N.json` for shard K of N > 1.
std::string annotations_file_name(const batch::BatchPlan& plan);

/// `whole` with its plan's shard set to K of N: the settings shard K's file holds in its info.
DatasetSettings shard_settings(DatasetSettings whole, unsigned k, unsigned n);

/// The images and annotations of `text`, a file CocoDataset::to_json wrote with `settings`, as
/// entries_since's lines (add_entries takes them back). Throws core::ConfigError naming `source`:
/// with each field of its info that `settings` give another value (`every_s: expected 5.0000, got
/// 2.0000`), or with the first line that to_json would not have written.
std::string read_entries(const std::string& text, const DatasetSettings& settings,
                         const std::string& source);

/// The files `dir`/annotations_shardK-of-N.json, K = 1..N, that `export_dataset --shard K/N` wrote
/// for the plan of `whole`, merged into the dataset one unsharded run of the plan makes: `whole`'s
/// settings as shard 1/1, with every shard's images and annotations in id order, so that its
/// to_json is the unsharded run's file byte for byte. Throws core::ConfigError before reading one
/// when files are missing, naming them (the first ten), or naming the file that cannot be read,
/// is not that shard's file of the plan (read_entries) or holds an image another shard holds.
CocoDataset merge_shard_files(const std::string& dir, DatasetSettings whole, unsigned shard_count);

}  // namespace ari_social_sim::dataset
