#pragma once
// Which axis-aligned boxes overlap, by sweeping along x: sorting and one pass instead of testing every
// pair, so checks over many polygons or edges (world validation, polygon simplicity) grow with the
// boxes and their overlaps, not with their square.

#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "common/span.hpp"

namespace ifar::geometry {

/// Every pair (i, j), i < j, of `boxes` that overlap or come within `tolerance` of each other, sorted.
/// Empty boxes overlap nothing.
std::vector<std::pair<std::size_t, std::size_t>> overlappingBoxPairs(
    common::Span<const Eigen::AlignedBox2d> boxes, double tolerance = 0.0);

}  // namespace ifar::geometry
