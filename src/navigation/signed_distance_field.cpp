#include "ari_social_sim/navigation/signed_distance_field.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace ari_social_sim::navigation {

GridField signed_distance_field(const model::OccupancyGrid& grid) {
  GridField field(grid, 0.0f);
  if (grid.width == 0 || grid.height == 0) {
    return field;
  }
  cv::Mat free_mask(grid.height, grid.width, CV_8UC1);
  size_t free_count = 0;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const bool is_free = grid.at(x, y) == model::OccupancyGrid::kFree;
      free_mask.at<uint8_t>(y, x) = is_free ? 255 : 0;
      free_count += is_free ? 1 : 0;
    }
  }
  const double res = grid.resolution_m;
  if (free_count == grid.cells.size()) {
    const float far = static_cast<float>(res * std::hypot(grid.width, grid.height));
    std::fill(field.values().begin(), field.values().end(), far);
    return field;
  }
  cv::Mat occupied_mask;
  cv::bitwise_not(free_mask, occupied_mask);
  // Distance (in cells) from each non-zero pixel to the nearest zero pixel, centre to centre; the
  // edge between the two cells lies half a cell closer.
  cv::Mat to_occupied, to_free;
  cv::distanceTransform(free_mask, to_occupied, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  cv::distanceTransform(occupied_mask, to_free, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const bool any_free = free_count > 0;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (free_mask.at<uint8_t>(y, x) != 0) {
        field.at(x, y) = static_cast<float>((to_occupied.at<float>(y, x) - 0.5) * res);
      } else {
        const double cells =
            any_free ? to_free.at<float>(y, x) : std::hypot(grid.width, grid.height);
        field.at(x, y) = static_cast<float>(-(cells - 0.5) * res);
      }
    }
  }
  return field;
}

}  // namespace ari_social_sim::navigation
