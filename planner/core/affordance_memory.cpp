#include "planner/core/affordance_memory.hpp"

#include <limits>

namespace ifar::planner {

AffordanceMemory::AffordanceMemory(double match_distance_m) : match_distance_m_(match_distance_m) {}

void AffordanceMemory::learned(std::int64_t object_id, bool pushable,
                               const interaction::ObjectPhysics& physics,
                               const std::optional<geometry::Point>& centroid)
{
  LearnedAffordance& entry = tracked_[object_id];
  if (centroid) {
    entry.centroid = centroid;
  }
  // Once unpushable, always (as the interaction stage holds it): a later estimate does not undo it.
  entry.pushable = entry.pushable && pushable;
  entry.physics = physics;
}

void AffordanceMemory::seen(const std::vector<TrackedObject>& objects)
{
  for (const TrackedObject& object : objects) {
    const auto found = tracked_.find(object.id);
    if (found != tracked_.end()) {
      found->second.centroid = object.centroid;
    }
  }
}

void AffordanceMemory::dropped(std::int64_t object_id)
{
  const auto found = tracked_.find(object_id);
  if (found == tracked_.end()) {
    return;
  }
  if (found->second.centroid) {
    lost_.push_back(found->second);
  }
  tracked_.erase(found);
}

std::optional<LearnedAffordance> AffordanceMemory::inherit(std::int64_t object_id,
                                                           const geometry::Point& centroid)
{
  if (tracked_.count(object_id) != 0 || !centroid.allFinite()) {
    return std::nullopt;
  }
  std::size_t nearest = lost_.size();
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (std::size_t index = 0; index < lost_.size(); ++index) {
    const double distance = (*lost_[index].centroid - centroid).norm();
    if (distance <= match_distance_m_ && distance < nearest_distance) {
      nearest = index;
      nearest_distance = distance;
    }
  }
  if (nearest == lost_.size()) {
    return std::nullopt;
  }
  LearnedAffordance entry = lost_[nearest];
  lost_.erase(lost_.begin() + static_cast<std::ptrdiff_t>(nearest));
  entry.centroid = centroid;
  tracked_[object_id] = entry;
  return entry;
}

}  // namespace ifar::planner
