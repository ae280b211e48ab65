#include "planner/interaction/interaction_cache.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "planner/interaction/convex_polygon.hpp"

namespace ifar::interaction {

using geometry::Point;
using geometry::Polygon;

namespace {

std::size_t foundCount(const ObjectInteractions& interactions)
{
  return static_cast<std::size_t>(
      std::count_if(interactions.plans.begin(), interactions.plans.end(),
                    [](const PairPlan& plan) { return plan.plan.status == PlanStatus::Found; }));
}

}  // namespace

InteractionCache::InteractionCache(const InteractionSettings& settings, double outline_cell_m)
    : settings_(settings), outline_cell_m_(outline_cell_m)
{
}

InteractionCache::Signature InteractionCache::signatureOf(const LocalScene& scene, std::size_t movable_index,
                                                          const ObjectPhysics& physics,
                                                          const std::optional<Bounds>& window,
                                                          Neighbours neighbours) const
{
  Signature signature;
  signature.physics = physics;
  if (movable_index >= scene.movable.size() || scene.movable[movable_index].size() < 3) {
    return signature;
  }
  const Polygon& object = scene.movable[movable_index];
  signature.object_centroid = geometry::centroid(object);
  signature.object_area = geometry::area(object);
  signature.object_perimeter = geometry::perimeter(object);
  if (window) {
    signature.window = *window;
  } else {
    signature.window = boundsOf(object);
    signature.window.minimum -= Point::Constant(settings_.connectivity.window_margin_m);
    signature.window.maximum += Point::Constant(settings_.connectivity.window_margin_m);
  }
  const Bounds& bounds = signature.window;
  const Polygon window_polygon{bounds.minimum, Point(bounds.maximum.x(), bounds.minimum.y()), bounds.maximum,
                               Point(bounds.minimum.x(), bounds.maximum.y())};
  Point moment = Point::Zero();
  const auto add = [&](const Polygon& polygon) {
    if (polygon.size() < 3 || !boundsOf(polygon).overlaps(bounds)) {
      return;
    }
    // The part inside the window (a non-convex obstacle by its hull: only a summary is needed).
    const Polygon convex =
        geometry::isConvex(polygon) ? geometry::counterClockwise(polygon) : geometry::convexHull(polygon);
    const Polygon inside = clipConvex(convex, window_polygon);
    if (inside.size() < 3) {
      return;
    }
    const double inside_area = geometry::area(inside);
    signature.neighbour_area += inside_area;
    moment += inside_area * geometry::centroid(inside);
  };
  for (const Polygon& polygon : scene.background) {
    add(polygon);
  }
  for (std::size_t index = 0; index < scene.movable.size(); ++index) {
    if (neighbours == Neighbours::All && index != movable_index) {
      add(scene.movable[index]);
    }
  }
  if (signature.neighbour_area > 0.0) {
    signature.neighbour_centroid = moment / signature.neighbour_area;
  }
  return signature;
}

bool InteractionCache::sameSurroundings(const Signature& first, const Signature& second) const
{
  return std::abs(first.neighbour_area - second.neighbour_area) <= kAreaToleranceM2 &&
         (first.neighbour_centroid - second.neighbour_centroid).norm() <= shiftTolerance() &&
         first.physics.ground_friction == second.physics.ground_friction &&
         first.physics.mass_kg == second.physics.mass_kg;
}

bool InteractionCache::same(const Signature& first, const Signature& second) const
{
  // Half a cell along the outline: what the raster alone changes of the object's area.
  const double raster_band_m2 =
      0.5 * outline_cell_m_ * std::max(first.object_perimeter, second.object_perimeter);
  return (first.object_centroid - second.object_centroid).norm() <= shiftTolerance() &&
         std::abs(first.object_area - second.object_area) <=
             std::max(0.1 * std::max(first.object_area, second.object_area), raster_band_m2) &&
         sameSurroundings(first, second);
}

bool InteractionCache::keepsPlans(const Entry& entry, const LocalScene& scene, std::size_t movable_index,
                                  const Signature& signature, const ObjectInteractions& fresh) const
{
  // The surroundings are compared in the window the kept plans were found in: the view's own window
  // grows and shrinks with the object's outline and takes in more or less wall with it. Only the static
  // ones: a neighbouring object's outline changes with the view as this one's does (a box beside a door
  // loses part of its outline whenever the vehicle comes up to the door's light box; were that a change
  // of surroundings, the route would swing between the push through the door and the way round).
  return entry.valid && foundCount(fresh) < foundCount(entry.interactions) &&
         (signature.object_centroid - entry.planned.object_centroid).norm() <= kKeepRadiusM &&
         sameSurroundings(entry.planned, signatureOf(scene, movable_index, signature.physics,
                                                     entry.planned.window, Neighbours::StaticOnly));
}

bool InteractionCache::stale(std::int64_t object_id, const LocalScene& scene, std::size_t movable_index,
                             const ObjectPhysics& physics) const
{
  const auto found = entries_.find(object_id);
  return found == entries_.end() || !found->second.valid ||
         !same(found->second.signature, signatureOf(scene, movable_index, physics));
}

const ObjectInteractions& InteractionCache::interactionsFor(std::int64_t object_id, const LocalScene& scene,
                                                            std::size_t movable_index,
                                                            const ObjectPhysics& physics, bool& replanned)
{
  const Signature signature = signatureOf(scene, movable_index, physics);
  Entry& entry = entries_[object_id];  // a new object's entry is not valid: stale
  replanned = !entry.valid || !same(entry.signature, signature);
  if (replanned) {
    ObjectInteractions fresh = planObjectInteractions(scene, movable_index, physics, settings_);
    if (keepsPlans(entry, scene, movable_index, signature, fresh)) {
      // This view is taken in (the next one like it is not planned again); its poorer plans are not.
      entry.signature = signature;
      replanned = false;
      return entry.interactions;
    }
    entry.signature = signature;
    entry.interactions = std::move(fresh);
    entry.planned = signatureOf(scene, movable_index, physics, signature.window, Neighbours::StaticOnly);
    entry.valid = true;
  }
  return entry.interactions;
}

void InteractionCache::invalidate(std::int64_t object_id)
{
  const auto found = entries_.find(object_id);
  if (found != entries_.end()) {
    found->second.valid = false;
  }
}

void InteractionCache::forget(std::int64_t object_id)
{
  entries_.erase(object_id);
}

}  // namespace ifar::interaction
