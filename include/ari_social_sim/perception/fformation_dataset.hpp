#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/grouping.hpp"

// Readers of the F-formation data sets converted to CSV (docs/perception_gcff.md). Each file
// starts with its exact header line; fields are separated by commas, without quoting; spaces
// around a field and a trailing '\r' are ignored; blank lines are skipped. Anything else throws
// core::ConfigError naming the file, the line, the column (1-based character position of the
// field) and the field, e.g. `Synth_features.csv:12:9: x: expected a finite number, got "abc"`.

namespace ari_social_sim::perception {

/// The people of each frame, in file order.
using FeatureTable = std::map<FrameId, std::vector<GcffPerson>>;

/// Reads `frame,person_id,x,y,theta` (positions in the data set's unit, theta in rad). Frames are
/// integers, person ids non-empty text copied unchanged; a person listed twice in a frame is an
/// error.
FeatureTable read_fformation_features(const std::string& path);

/// Reads `frame,group,person_id`: ground-truth groups per frame, in order of the group label's
/// first appearance, members in file order. Group labels are non-empty text local to their frame;
/// a person in two groups of the same frame is an error.
GroupTable read_fformation_groups(const std::string& path);

/// Reads `frame`: the annotated frames, in file order; a repeated frame is an error.
std::vector<FrameId> read_fformation_frames(const std::string& path);

/// Runs GCFF on every frame of `features`: the detected groups (two or more people) by person id,
/// members in input order, with an entry for every frame. `stop`, when given, is asked before each
/// frame: once it says true, the frames done are returned, an entry for each (a tool stopped by a
/// signal). Throws core::ConfigError for invalid `params`.
GroupTable detect_fformation_groups(const FeatureTable& features, const GcffParams& params,
                                    const std::function<bool()>& stop = nullptr);

}  // namespace ari_social_sim::perception
