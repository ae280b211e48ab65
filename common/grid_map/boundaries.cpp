#include "common/grid_map/boundaries.hpp"

#include <array>
#include <cstdint>

namespace ifar::grid_map {
namespace {

// Unit steps along the grid lines, counter-clockwise: +x, +y, -x, -y.
constexpr std::array<int, 4> kStepX = {1, 0, -1, 0};
constexpr std::array<int, 4> kStepY = {0, 1, 0, -1};

}  // namespace

std::vector<geometry::Polygon> blockedBoundaries(const GridMap& map, UnknownPolicy policy)
{
  const int width = map.width();
  const int height = map.height();
  const std::size_t points_per_row = static_cast<std::size_t>(width) + 1;
  const auto pointIndex = [&](int x, int y) {
    return static_cast<std::size_t>(y) * points_per_row + static_cast<std::size_t>(x);
  };
  // has_edge[point * 4 + direction]: a unit boundary edge leaves lattice point `point` in `direction`
  // with the blocked cell on its left. 2 = already traced.
  std::vector<std::uint8_t> has_edge(points_per_row * (static_cast<std::size_t>(height) + 1) * 4, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (map.blocked(x, y, policy)) {
        continue;
      }
      // For a blocked neighbour in direction n the edge runs along rotate(n, -90 degrees).
      if (map.blocked(x + 1, y, policy)) {
        has_edge[pointIndex(x + 1, y + 1) * 4 + 3] = 1;
      }
      if (map.blocked(x - 1, y, policy)) {
        has_edge[pointIndex(x, y) * 4 + 1] = 1;
      }
      if (map.blocked(x, y + 1, policy)) {
        has_edge[pointIndex(x, y + 1) * 4 + 0] = 1;
      }
      if (map.blocked(x, y - 1, policy)) {
        has_edge[pointIndex(x + 1, y) * 4 + 2] = 1;
      }
    }
  }

  std::vector<geometry::Polygon> loops;
  for (int start_y = 0; start_y <= height; ++start_y) {
    for (int start_x = 0; start_x <= width; ++start_x) {
      for (int start_direction = 0; start_direction < 4; ++start_direction) {
        if (has_edge[pointIndex(start_x, start_y) * 4 + static_cast<std::size_t>(start_direction)] != 1) {
          continue;
        }
        geometry::Polygon loop;
        int x = start_x;
        int y = start_y;
        int direction = start_direction;
        int previous_direction = -1;
        while (true) {
          has_edge[pointIndex(x, y) * 4 + static_cast<std::size_t>(direction)] = 2;
          if (direction != previous_direction) {
            loop.push_back(map.cornerToWorld(x, y));
          }
          x += kStepX[static_cast<std::size_t>(direction)];
          y += kStepY[static_cast<std::size_t>(direction)];
          // Right turn first: where two blocked cells touch diagonally the loop keeps following the
          // free cell on its right, which joins the blocked cells into one region (no squeezing through).
          const std::array<int, 3> choices = {(direction + 3) % 4, direction, (direction + 1) % 4};
          int next = -1;
          for (const int candidate : choices) {
            if (has_edge[pointIndex(x, y) * 4 + static_cast<std::size_t>(candidate)] != 0) {
              next = candidate;
              break;
            }
          }
          const bool closed = x == start_x && y == start_y;
          if (next < 0 || (closed && next == start_direction) ||
              has_edge[pointIndex(x, y) * 4 + static_cast<std::size_t>(next)] == 2) {
            // Back at the start: drop the start vertex if the loop arrives straight through it.
            if (closed && direction == start_direction && loop.size() > 1) {
              loop.erase(loop.begin());
            }
            break;
          }
          previous_direction = direction;
          direction = next;
        }
        loops.push_back(std::move(loop));
      }
    }
  }
  return loops;
}

}  // namespace ifar::grid_map
