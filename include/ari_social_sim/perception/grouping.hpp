#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ari_social_sim::perception {

/// Frame number of a recorded data set (the `frame` column of the F-formation CSVs).
using FrameId = int64_t;

/// The groups of one frame, each a list of person ids (ROS4HRI ids are strings, so are these).
using Grouping = std::vector<std::vector<std::string>>;

/// Groups per frame; a frame without an entry has no groups.
using GroupTable = std::map<FrameId, Grouping>;

}  // namespace ari_social_sim::perception
