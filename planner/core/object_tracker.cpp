#include "planner/core/object_tracker.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "planner/interaction/convex_polygon.hpp"

namespace ifar::planner {

namespace {

struct Box {
  geometry::Point minimum = geometry::Point::Constant(std::numeric_limits<double>::infinity());
  geometry::Point maximum = geometry::Point::Constant(-std::numeric_limits<double>::infinity());

  bool contains(const geometry::Point& point, double margin) const
  {
    return point.x() >= minimum.x() - margin && point.x() <= maximum.x() + margin &&
           point.y() >= minimum.y() - margin && point.y() <= maximum.y() + margin;
  }
  bool overlaps(const Box& other) const
  {
    return minimum.x() <= other.maximum.x() && other.minimum.x() <= maximum.x() &&
           minimum.y() <= other.maximum.y() && other.minimum.y() <= maximum.y();
  }
};

Box boxOf(const geometry::Polygon& polygon)
{
  Box box;
  for (const geometry::Point& point : polygon) {
    box.minimum = box.minimum.cwiseMin(point);
    box.maximum = box.maximum.cwiseMax(point);
  }
  return box;
}

geometry::Point centreOf(const geometry::Polygon& polygon)
{
  if (polygon.size() >= 3 && geometry::area(polygon) > 1e-9) {
    return geometry::centroid(polygon);
  }
  geometry::Point sum = geometry::Point::Zero();
  for (const geometry::Point& point : polygon) {
    sum += point;
  }
  return polygon.empty() ? sum : geometry::Point(sum / static_cast<double>(polygon.size()));
}

struct Candidate {
  double distance;
  std::size_t track;
  std::size_t outline;
};

}  // namespace

ObjectTracker::ObjectTracker(const TrackerSettings& settings) : settings_(settings) {}

bool ObjectTracker::contains(std::int64_t id) const
{
  return std::any_of(tracks_.begin(), tracks_.end(), [id](const Track& track) { return track.id == id; });
}

std::optional<geometry::Point> ObjectTracker::centroidOf(std::int64_t id) const
{
  const auto found =
      std::find_if(tracks_.begin(), tracks_.end(), [id](const Track& track) { return track.id == id; });
  if (found == tracks_.end()) {
    return std::nullopt;
  }
  return found->centroid;
}

geometry::Polygon ObjectTracker::outlineOf(std::int64_t id) const
{
  const auto found =
      std::find_if(tracks_.begin(), tracks_.end(), [id](const Track& track) { return track.id == id; });
  return found == tracks_.end() ? geometry::Polygon{} : found->outline;
}

std::optional<std::int64_t> ObjectTracker::nearestTo(const geometry::Segment& segment, double radius) const
{
  std::optional<std::int64_t> nearest;
  double nearest_distance = radius;
  for (const Track& track : tracks_) {
    if (track.outline.size() < 3) {
      continue;
    }
    const double distance = interaction::segmentPolygonDistance(segment, track.outline);
    if (distance <= nearest_distance) {
      nearest = track.id;
      nearest_distance = distance;
    }
  }
  return nearest;
}

bool ObjectTracker::forget(std::int64_t id)
{
  const auto found =
      std::find_if(tracks_.begin(), tracks_.end(), [id](const Track& track) { return track.id == id; });
  if (found == tracks_.end()) {
    return false;
  }
  tracks_.erase(found);
  return true;
}

TrackingResult ObjectTracker::update(const std::vector<geometry::Polygon>& outlines,
                                     const geometry::Point& vehicle,
                                     const std::function<bool(const geometry::Point&)>& in_sight)
{
  TrackingResult result;
  constexpr std::size_t kUnassigned = std::numeric_limits<std::size_t>::max();
  std::vector<geometry::Point> centres;
  std::vector<Box> boxes;
  for (const geometry::Polygon& outline : outlines) {
    centres.push_back(centreOf(outline));
    boxes.push_back(boxOf(outline));
  }
  std::vector<Box> track_boxes;
  track_boxes.reserve(tracks_.size());
  for (const Track& track : tracks_) {
    track_boxes.push_back(boxOf(track.outline));
  }

  // An outline may be an object when the centroids are close or the object's centre lies in it.
  std::vector<Candidate> candidates;
  for (std::size_t track = 0; track < tracks_.size(); ++track) {
    for (std::size_t outline = 0; outline < outlines.size(); ++outline) {
      const double distance = (tracks_[track].centroid - centres[outline]).norm();
      const bool covers = boxes[outline].contains(tracks_[track].centroid, 0.0) ||
                          track_boxes[track].contains(centres[outline], 0.0);
      if (distance <= settings_.association_distance_m || covers) {
        candidates.push_back({distance, track, outline});
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });

  // One-to-one first, closest pairs first; then split pieces join the object they lie on.
  std::vector<std::size_t> outline_track(outlines.size(), kUnassigned);
  std::vector<bool> track_matched(tracks_.size(), false);
  for (const Candidate& candidate : candidates) {
    if (outline_track[candidate.outline] == kUnassigned && !track_matched[candidate.track]) {
      outline_track[candidate.outline] = candidate.track;
      track_matched[candidate.track] = true;
    }
  }
  for (const Candidate& candidate : candidates) {
    if (outline_track[candidate.outline] == kUnassigned && track_matched[candidate.track] &&
        track_boxes[candidate.track].overlaps(boxes[candidate.outline])) {
      outline_track[candidate.outline] = candidate.track;
    }
  }
  // Objects whose outline merged with a neighbour's: covered, so not missing, and their old outline stays.
  std::vector<bool> track_covered(tracks_.size(), false);
  for (const Candidate& candidate : candidates) {
    if (!track_matched[candidate.track] && outline_track[candidate.outline] != kUnassigned &&
        boxes[candidate.outline].contains(tracks_[candidate.track].centroid, 0.0)) {
      track_covered[candidate.track] = true;
    }
  }

  // New objects for outlines nobody claimed.
  std::vector<Track> added;
  std::vector<std::int64_t> outline_id(outlines.size(), 0);
  for (std::size_t outline = 0; outline < outlines.size(); ++outline) {
    if (outline_track[outline] != kUnassigned) {
      outline_id[outline] = tracks_[outline_track[outline]].id;
      continue;
    }
    // A piece next to an outline already given a new id this frame (a split new object) shares it.
    std::int64_t shared = 0;
    for (std::size_t other = 0; other < outline && shared == 0; ++other) {
      if (outline_track[other] == kUnassigned && outline_id[other] > 0 &&
          boxes[other].overlaps(boxes[outline])) {
        shared = outline_id[other];
      }
    }
    outline_id[outline] = shared > 0 ? shared : next_id_++;
  }

  // Refresh the matched tracks' outlines (the hull of all their pieces) and count misses.
  std::vector<Track> kept;
  for (std::size_t track = 0; track < tracks_.size(); ++track) {
    Track current = tracks_[track];
    if (track_matched[track]) {
      std::vector<geometry::Point> points;
      std::size_t pieces = 0;
      std::size_t last = 0;
      for (std::size_t outline = 0; outline < outlines.size(); ++outline) {
        if (outline_track[outline] == track) {
          points.insert(points.end(), outlines[outline].begin(), outlines[outline].end());
          ++pieces;
          last = outline;
        }
      }
      current.outline = pieces == 1 ? outlines[last] : geometry::convexHull(points);
      current.centroid = centreOf(current.outline);
      current.misses = 0;
      kept.push_back(std::move(current));
      continue;
    }
    const bool in_view = (current.centroid - vehicle).norm() <= settings_.view_radius_m &&
                         (!in_sight || in_sight(current.centroid));
    if (!track_covered[track] && in_view) {
      ++current.misses;
    }
    if (current.misses >= settings_.drop_after_frames) {
      result.dropped.push_back(current.id);
    } else {
      kept.push_back(std::move(current));
    }
  }
  // New tracks, pieces of one new object joined.
  for (std::size_t outline = 0; outline < outlines.size(); ++outline) {
    if (outline_track[outline] != kUnassigned) {
      continue;
    }
    const auto existing = std::find_if(added.begin(), added.end(),
                                       [&](const Track& track) { return track.id == outline_id[outline]; });
    if (existing == added.end()) {
      Track track;
      track.id = outline_id[outline];
      track.outline = outlines[outline];
      track.centroid = centres[outline];
      added.push_back(std::move(track));
    } else {
      std::vector<geometry::Point> points = existing->outline;
      points.insert(points.end(), outlines[outline].begin(), outlines[outline].end());
      existing->outline = geometry::convexHull(points);
      existing->centroid = centreOf(existing->outline);
    }
  }
  std::vector<std::int64_t> seen_ids;
  for (std::size_t track = 0; track < tracks_.size(); ++track) {
    if (track_matched[track]) {
      seen_ids.push_back(tracks_[track].id);
    }
  }
  kept.insert(kept.end(), added.begin(), added.end());
  tracks_ = std::move(kept);
  std::sort(tracks_.begin(), tracks_.end(), [](const Track& a, const Track& b) { return a.id < b.id; });

  for (const Track& track : tracks_) {
    const bool seen = std::find(seen_ids.begin(), seen_ids.end(), track.id) != seen_ids.end() ||
                      std::any_of(added.begin(), added.end(),
                                  [&](const Track& new_track) { return new_track.id == track.id; });
    if (seen) {
      result.seen.push_back(TrackedObject{track.id, track.outline, track.centroid});
    }
  }
  result.polygon_ids = std::move(outline_id);
  return result;
}

}  // namespace ifar::planner
