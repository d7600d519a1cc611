#include "ari_social_sim/audio/room_acoustics.hpp"

#include <algorithm>
#include <optional>

#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::audio {
namespace {

// Closer than this, a source is taken to be this far: no infinite gain at a microphone.
constexpr double kMinDistanceM = 0.1;

SoundPath path_over(double distance_m, double reflection) {
  const double distance = std::max(distance_m, kMinDistanceM);
  return {distance / kSpeedOfSoundMps, reflection / distance};
}

// The image of `source` in `wall`, when the reflection towards `microphone` hits the wall itself
// (not its extension) and both are on the same side of it.
std::optional<Eigen::Vector3d> image_in(const Wall& wall, const Eigen::Vector3d& source,
                                        const Eigen::Vector3d& microphone) {
  const Eigen::Vector2d along = wall.b - wall.a;
  const double length_sq = along.squaredNorm();
  if (length_sq < 1e-12) {
    return std::nullopt;
  }
  const Eigen::Vector2d normal = Eigen::Vector2d(-along.y(), along.x()).normalized();
  const double source_side = normal.dot(source.head<2>() - wall.a);
  const double microphone_side = normal.dot(microphone.head<2>() - wall.a);
  if (source_side * microphone_side <= 0.0) {
    return std::nullopt;
  }
  const Eigen::Vector2d mirrored = source.head<2>() - 2.0 * source_side * normal;
  // Where the line from the image to the microphone crosses the wall's line.
  const double to_wall = source_side / (source_side + microphone_side);
  const Eigen::Vector2d hit = mirrored + to_wall * (microphone.head<2>() - mirrored);
  const double t = (hit - wall.a).dot(along) / length_sq;
  if (t < 0.0 || t > 1.0) {
    return std::nullopt;
  }
  return Eigen::Vector3d(mirrored.x(), mirrored.y(), source.z());
}

}  // namespace

void check_room_settings(const RoomSettings& settings) {
  core::check_fields(settings, "RoomSettings");
}

std::vector<SoundPath> sound_paths(const Eigen::Vector3d& source, const Eigen::Vector3d& microphone,
                                   const std::vector<Wall>& walls, const RoomSettings& settings) {
  std::vector<SoundPath> paths{path_over((source - microphone).norm(), 1.0)};
  const Eigen::Vector3d below_floor(source.x(), source.y(), -source.z());
  paths.push_back(path_over((below_floor - microphone).norm(), settings.floor_reflection));
  for (const Wall& wall : walls) {
    if (const std::optional<Eigen::Vector3d> image = image_in(wall, source, microphone)) {
      paths.push_back(path_over((*image - microphone).norm(), settings.wall_reflection));
    }
  }
  return paths;
}

}  // namespace ari_social_sim::audio
