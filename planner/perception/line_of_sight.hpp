#pragma once
// Whether the layer's background (walls, inflated) lies across a line: the tracker counts an object as
// missing only where the vehicle could have seen it, not while it sits behind a wall or a door post.

#include "common/geometry/point.hpp"
#include "planner/perception/local_layer.hpp"

namespace ifar::perception {

/// True when no background cell of `layer` lies on the segment `from` -> `to` after leaving out
/// `skip_m` at each end (the vehicle may squeeze inside a wall's inflation, and an object's centre may sit
/// inside the inflation of the wall it leans on). Cells outside the raster are unknown: they block nothing.
bool backgroundClearAlong(const LocalLayer& layer, const geometry::Point& from, const geometry::Point& to,
                          double skip_m);

}  // namespace ifar::perception
