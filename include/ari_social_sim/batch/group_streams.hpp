#pragma once

#include <cstddef>
#include <string>

#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::batch {

/// Counts of what GroupStreams wrote, for a run's summary and its tests.
struct GroupStreamCounts {
  size_t frames{0};
  size_t feature_rows{0};  ///< People perceived at their bodies, summed over the frames.
  size_t world_groups{0};  ///< The world's groups of two or more members, summed over the frames.
  size_t truth_groups{0};  ///< Those of them with two or more members perceived.
  size_t truth_rows{0};    ///< Their perceived members.
};

/// A run's perceived people and true groups, frame by frame, as the three CSV files of an
/// F-formation data set that detect_groups reads (perception/fformation_dataset.hpp,
/// docs/perception_gcff.md "GCFF on perceived streams"):
///
/// - features `frame,person_id,x,y,theta`: every person perception tracks with a body, at that
///   body's perceived pose in the map (metres, rad), under the person id perception reports: the
///   people GCFF is given in the engine and in group_detection_node (group_candidates_of);
/// - ground truth `frame,group,person_id`: the world's groups of two or more members, each
///   member named by the person id perception gives them. Members perception does not report at
///   a body that frame are left out, and so is a group with fewer than two members left: a
///   detector cannot be asked to find people it was not given;
/// - frames `frame`: every frame added, with people or not.
///
/// Frames are numbered 0, 1, ... in the order they are added, across runs. Positions are written
/// with 4 decimals (0.1 mm), angles with 5, so the same frames give the same bytes.
class GroupStreams {
 public:
  GroupStreams();

  /// Adds `frame`, perceived from the world state `world` (the same step). The world's group
  /// ids label the truth's groups.
  void add(const world::WorldSnapshot& world, const perception::PerceptionFrame& frame);

  const std::string& features_csv() const { return features_; }
  const std::string& groundtruth_csv() const { return truth_; }
  const std::string& frames_csv() const { return frames_; }
  const GroupStreamCounts& counts() const { return counts_; }

 private:
  std::string features_;
  std::string truth_;
  std::string frames_;
  GroupStreamCounts counts_;
};

}  // namespace ari_social_sim::batch
