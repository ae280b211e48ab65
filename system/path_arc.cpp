#include "system/path_arc.hpp"

#include <algorithm>
#include <utility>

#include "common/geometry/segment.hpp"

namespace ifar::runner {

PathArc::PathArc(std::vector<geometry::Point> polyline)
    : polyline_(std::move(polyline)), arc_(polyline_.size(), 0.0)
{
  for (std::size_t index = 1; index < polyline_.size(); ++index) {
    arc_[index] = arc_[index - 1] + (polyline_[index] - polyline_[index - 1]).norm();
  }
}

PathArc::Foot PathArc::nearest(const geometry::Point& point, double arc_min, double arc_max) const
{
  if (polyline_.size() < 2) {
    const geometry::Point only = polyline_.empty() ? geometry::Point::Zero() : polyline_.front();
    return Foot{0, only, 0.0, (point - only).norm()};
  }
  arc_min = std::clamp(arc_min, 0.0, length());
  arc_max = std::clamp(arc_max, arc_min, length());
  Foot best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t index = 0; index + 1 < polyline_.size(); ++index) {
    const double begin = arc_[index];
    const double end = arc_[index + 1];
    if (end < arc_min || begin > arc_max) {
      continue;
    }
    // The segment's part within the stretch, then the nearest point of that part.
    const geometry::Point direction = polyline_[index + 1] - polyline_[index];
    const double segment_length = end - begin;
    const auto at = [&](double arc) {
      return segment_length > 0.0 ? polyline_[index] + direction * ((arc - begin) / segment_length)
                                  : polyline_[index];
    };
    const double from = std::max(begin, arc_min);
    const double to = std::min(end, arc_max);
    const geometry::Point first = at(from);
    const geometry::Point last = at(to);
    const geometry::Point foot = geometry::closestPointOnSegment(point, {first, last});
    const double distance = (point - foot).norm();
    if (distance < best.distance) {
      best = Foot{index, foot, from + (foot - first).norm(), distance};
    }
  }
  return best;
}

std::vector<geometry::Point> PathArc::remainderFrom(const geometry::Point& point) const
{
  const Foot foot = nearest(point);
  std::vector<geometry::Point> remainder{point, foot.point};
  if (foot.segment + 1 < polyline_.size()) {
    remainder.insert(remainder.end(), polyline_.begin() + static_cast<std::ptrdiff_t>(foot.segment) + 1,
                     polyline_.end());
  }
  return remainder;
}

}  // namespace ifar::runner
