#include "planner/interaction/polyline_samples.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::interaction {

void samplePolyline(const std::vector<geometry::Point>& polyline, double spacing,
                    std::vector<geometry::Point>& samples, double& length)
{
  length = 0.0;
  if (polyline.empty()) {
    return;
  }
  samples.push_back(polyline.front());
  for (std::size_t index = 1; index < polyline.size(); ++index) {
    const geometry::Vector step = polyline[index] - polyline[index - 1];
    const double segment_length = step.norm();
    const int pieces = std::max(1, static_cast<int>(std::ceil(segment_length / spacing)));
    for (int piece = 1; piece <= pieces; ++piece) {
      samples.push_back(polyline[index - 1] + step * (static_cast<double>(piece) / pieces));
    }
    length += segment_length;
  }
}

std::vector<geometry::Point> outlineSamples(const geometry::Polygon& polygon, double spacing)
{
  std::vector<geometry::Point> outline = polygon;
  outline.push_back(polygon.front());
  std::vector<geometry::Point> samples;
  double perimeter = 0.0;
  samplePolyline(outline, spacing, samples, perimeter);
  return samples;
}

}  // namespace ifar::interaction
