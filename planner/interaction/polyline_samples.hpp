#pragma once
// Points at a fixed spacing along polylines and round polygons: what the push search checks against
// obstacles where checking every point of a line would be exact but slow.

#include <vector>

#include "common/geometry/polygon.hpp"

namespace ifar::interaction {

/// Appends points every `spacing` (or a little less) along `polyline` to `samples`, both end points
/// included, and sets `length` to the polyline's length.
void samplePolyline(const std::vector<geometry::Point>& polyline, double spacing,
                    std::vector<geometry::Point>& samples, double& length);

/// Points every `spacing` round the closed `polygon`, starting and ending at its first vertex.
std::vector<geometry::Point> outlineSamples(const geometry::Polygon& polygon, double spacing);

}  // namespace ifar::interaction
