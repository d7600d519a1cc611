#pragma once

#include <string>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::model {

/// Reads a world file (format in docs/world.md):
///
///   name: two_room_flat
///   origin: [0, 0]          # m, lower-left corner of the floor
///   size: [10, 6]           # m
///   objects:
///     - {type: wall, from: [0, 0], to: [10, 0], thickness: 0.1}
///     - {type: box, name: couch, position: [2, 5], orientation: 0, size: [2, 0.8]}
///     - {type: circle, name: table, position: [7, 2], radius: 0.4}
///     - {type: polygon, name: desk, points: [[1, 1], [2, 1], [2, 2]]}
///
/// Throws core::ConfigError naming the file, the entry and the field on any malformed value
/// (unknown type, missing field, wrong type, non-positive size, non-convex polygon, duplicate id).
WorldDescription load_world_file(const std::string& path);
/// The same from an already-parsed mapping (tests and inline worlds).
WorldDescription parse_world(const core::YamlMap& root);

}  // namespace ari_social_sim::model
