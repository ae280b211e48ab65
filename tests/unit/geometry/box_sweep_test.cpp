#include "common/geometry/box_sweep.hpp"

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace ifar::geometry {
namespace {

std::vector<std::pair<std::size_t, std::size_t>> everyPairThatMeets(
    const std::vector<Eigen::AlignedBox2d>& boxes, double tolerance)
{
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t first = 0; first < boxes.size(); ++first) {
    for (std::size_t second = first + 1; second < boxes.size(); ++second) {
      const Eigen::AlignedBox2d& a = boxes[first];
      const Eigen::AlignedBox2d& b = boxes[second];
      if (!a.isEmpty() && !b.isEmpty() && a.min().x() <= b.max().x() + tolerance &&
          b.min().x() <= a.max().x() + tolerance && a.min().y() <= b.max().y() + tolerance &&
          b.min().y() <= a.max().y() + tolerance) {
        pairs.emplace_back(first, second);
      }
    }
  }
  return pairs;
}

TEST(BoxSweep, FindsExactlyThePairsThatMeet)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(0.0, 50.0);
  std::uniform_real_distribution<double> size(0.0, 4.0);
  std::vector<Eigen::AlignedBox2d> boxes;
  for (int index = 0; index < 400; ++index) {
    const Eigen::Vector2d corner(position(random), position(random));
    boxes.emplace_back(corner, corner + Eigen::Vector2d(size(random), size(random)));
  }
  boxes.emplace_back();  // empty: meets nothing
  boxes.emplace_back(Eigen::Vector2d(60, 60), Eigen::Vector2d(61, 61));
  boxes.emplace_back(Eigen::Vector2d(61.05, 60), Eigen::Vector2d(62, 61));  // 5 cm from the one before
  for (const double tolerance : {0.0, 0.1}) {
    const auto swept =
        overlappingBoxPairs(common::Span<const Eigen::AlignedBox2d>(boxes.data(), boxes.size()), tolerance);
    EXPECT_EQ(swept, everyPairThatMeets(boxes, tolerance));
    const std::pair<std::size_t, std::size_t> gap(boxes.size() - 2, boxes.size() - 1);
    EXPECT_EQ(std::count(swept.begin(), swept.end(), gap), tolerance > 0.05 ? 1 : 0);
  }
  EXPECT_GT(everyPairThatMeets(boxes, 0.0).size(), 50U);  // the random boxes do meet
}

}  // namespace
}  // namespace ifar::geometry
