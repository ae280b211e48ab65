#include "executive/doorway/doorway.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ifar::executive {
namespace {

// The search's resolution: path samples, run skews and run offsets.
constexpr double kSampleStepM = 0.05;
constexpr double kSkewStepRad = 0.02;
constexpr double kOffsetStepM = 0.01;

geometry::Point leftOf(const geometry::Point& direction)
{
  return {-direction.y(), direction.x()};
}

/// The obstacle points within `reach` of `centre`.
std::vector<geometry::Point> pointsNear(common::Span<const geometry::Point> points,
                                        const geometry::Point& centre, double reach)
{
  std::vector<geometry::Point> near;
  for (const geometry::Point& point : points) {
    if ((point - centre).norm() <= reach) {
      near.push_back(point);
    }
  }
  return near;
}

struct PathSample {
  geometry::Point position;
  geometry::Point direction;  // unit
  double along_m = 0.0;       // path length from path[0]
};

/// Points along `path` every kSampleStepM from `from_m` to `to_m` of arc length.
std::vector<PathSample> samplePath(common::Span<const geometry::Point> path, double from_m, double to_m)
{
  std::vector<PathSample> samples;
  double travelled = 0.0;
  int step = static_cast<int>(std::ceil(from_m / kSampleStepM - 1e-9));
  for (std::size_t index = 0; index + 1 < path.size(); ++index) {
    const geometry::Point leg = path[index + 1] - path[index];
    const double length = leg.norm();
    if (!(length > 1e-9)) {
      continue;
    }
    const geometry::Point direction = leg / length;
    for (double at = step * kSampleStepM; at <= travelled + length + 1e-9 && at <= to_m + 1e-9;
         at = ++step * kSampleStepM) {
      samples.push_back({path[index] + (at - travelled) * direction, direction, at});
    }
    travelled += length;
    if (travelled > to_m) {
      break;
    }
  }
  return samples;
}

struct Gap {
  geometry::Point first_post;
  geometry::Point second_post;
  geometry::Point direction;  // of the path where it crosses
  double width_m = std::numeric_limits<double>::infinity();
};

/// The gap the path crosses at `sample`: the nearest point, and the nearest point on the far side of the
/// sample from it. None when there is no point on the far side or the path runs along the gap's line
/// (crosses it at a sine below `min_crossing_sine`).
std::optional<Gap> gapAt(const PathSample& sample, const std::vector<geometry::Point>& points,
                         double max_width, double min_crossing_sine)
{
  const geometry::Point* nearest = nullptr;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (const geometry::Point& point : points) {
    const double distance = (point - sample.position).norm();
    if (distance < nearest_distance) {
      nearest_distance = distance;
      nearest = &point;
    }
  }
  // A gap through the sample is at least twice the distance to its nearest point.
  if (nearest == nullptr || 2.0 * nearest_distance >= max_width) {
    return std::nullopt;
  }
  const geometry::Point toward_nearest = *nearest - sample.position;
  const geometry::Point* opposite = nullptr;
  double opposite_distance = std::numeric_limits<double>::infinity();
  for (const geometry::Point& point : points) {
    const geometry::Point offset = point - sample.position;
    if (offset.dot(toward_nearest) >= 0.0) {
      continue;
    }
    const double distance = offset.norm();
    if (distance < opposite_distance) {
      opposite_distance = distance;
      opposite = &point;
    }
  }
  if (opposite == nullptr) {
    return std::nullopt;
  }
  Gap gap;
  gap.first_post = *nearest;
  gap.second_post = *opposite;
  gap.direction = sample.direction;
  gap.width_m = (gap.second_post - gap.first_post).norm();
  const geometry::Point across = (gap.second_post - gap.first_post) / gap.width_m;
  const double crossing_sine =
      std::abs(across.x() * sample.direction.y() - across.y() * sample.direction.x());
  if (crossing_sine < min_crossing_sine) {
    return std::nullopt;
  }
  return gap;
}

struct Run {
  geometry::Point centre;
  geometry::Point heading;
  double clearance_m = -std::numeric_limits<double>::infinity();
};

/// The straight run through `gap` (skewed up to max_skew_rad from square to it, shifted across it) whose
/// swept footprint keeps furthest from `points`, with room to turn on the spot at its start.
Run bestRun(const Gap& gap, const std::vector<geometry::Point>& points, const Footprint& footprint,
            const DoorwaySettings& settings)
{
  const geometry::Point across = (gap.second_post - gap.first_post) / gap.width_m;
  geometry::Point square = leftOf(across);
  if (square.dot(gap.direction) < 0.0) {
    square = -square;
  }
  const geometry::Point middle = 0.5 * (gap.first_post + gap.second_post);
  const double behind_m = settings.approach_m + footprint.rear_m + settings.min_clearance_m;
  const double ahead_m = settings.exit_m + footprint.front_m + settings.min_clearance_m;
  const double turn_radius = footprint.bodyCentre().norm() + footprint.circumradius();
  const double free_half = std::max(0.0, 0.5 * gap.width_m - footprint.half_width_m);
  // Farther points lie beyond the run's ends or farther to its side than the gap is wide.
  const double reach = std::max(behind_m, ahead_m) + gap.width_m + turn_radius;
  const std::vector<geometry::Point> near = pointsNear(points, middle, reach);
  Run best;
  double best_score = -std::numeric_limits<double>::infinity();
  const auto consider = [&](double skew, double offset) {
    const geometry::Point heading(std::cos(skew) * square.x() - std::sin(skew) * square.y(),
                                  std::sin(skew) * square.x() + std::cos(skew) * square.y());
    const geometry::Point left = leftOf(heading);
    const geometry::Point centre = middle + offset * across;
    const geometry::Point start = centre - settings.approach_m * heading;
    double clearance = std::numeric_limits<double>::infinity();
    for (const geometry::Point& point : near) {
      const geometry::Point from_centre = point - centre;
      const double along = from_centre.dot(heading);
      if (along >= -behind_m && along <= ahead_m) {
        clearance = std::min(clearance, std::abs(from_centre.dot(left)) - footprint.half_width_m);
      }
      clearance = std::min(clearance, (point - start).norm() - turn_radius);
    }
    // Among equally clear runs, the one square to the gap and through its middle.
    const double score = clearance - 0.01 * std::abs(skew) - 0.01 * std::abs(offset);
    if (score > best_score) {
      best_score = score;
      best = {centre, heading, clearance};
      return true;
    }
    return false;
  };
  // Coarse to fine: a coarse grid of skews and offsets, then the fine grid around its best.
  double best_skew = 0.0;
  double best_offset = 0.0;
  const int coarse_skews = static_cast<int>(std::floor(settings.max_skew_rad / (3.0 * kSkewStepRad) + 1e-9));
  const int coarse_offsets = static_cast<int>(std::floor(free_half / (3.0 * kOffsetStepM) + 1e-9));
  for (int skew_step = -coarse_skews; skew_step <= coarse_skews; ++skew_step) {
    for (int offset_step = -coarse_offsets; offset_step <= coarse_offsets; ++offset_step) {
      if (consider(3.0 * kSkewStepRad * skew_step, 3.0 * kOffsetStepM * offset_step)) {
        best_skew = 3.0 * kSkewStepRad * skew_step;
        best_offset = 3.0 * kOffsetStepM * offset_step;
      }
    }
  }
  const double coarse_skew = best_skew;
  const double coarse_offset = best_offset;
  for (int skew_step = -2; skew_step <= 2; ++skew_step) {
    for (int offset_step = -2; offset_step <= 2; ++offset_step) {
      const double skew = coarse_skew + kSkewStepRad * skew_step;
      const double offset = coarse_offset + kOffsetStepM * offset_step;
      if ((skew_step != 0 || offset_step != 0) && std::abs(skew) <= settings.max_skew_rad + 1e-9 &&
          std::abs(offset) <= free_half + 1e-9) {
        consider(skew, offset);
      }
    }
  }
  return best;
}

/// Whether `position` lies between the posts: its foot on the line through them falls between them and it
/// is at most `off_line_m` from that line. A gap the path passes beside is not one it goes through.
bool between(const geometry::Point& position, const Gap& gap, double off_line_m)
{
  const geometry::Point across = gap.second_post - gap.first_post;
  const double fraction = across.dot(position - gap.first_post) / across.squaredNorm();
  const geometry::Point foot = gap.first_post + fraction * across;
  return fraction >= 0.0 && fraction <= 1.0 && (position - foot).norm() <= off_line_m;
}

}  // namespace

std::optional<ImpassableGap> findImpassableGap(common::Span<const geometry::Point> path,
                                               common::Span<const geometry::Point> obstacles,
                                               const Footprint& footprint, const DoorwaySettings& settings)
{
  if (path.size() < 2 || obstacles.empty() || footprint.front_m >= settings.look_ahead_m) {
    return std::nullopt;
  }
  // The same bound on what the footprint fits through as the doorway run's: a narrower gap is no doorway.
  const double passable_m = passableWidth(footprint, settings);
  // A gap narrower than the vehicle by more than the clearance is one the planner's inflation by the half
  // width closes once its scans show it: a path through it runs where the planner has not seen (two
  // points of one wall a few centimetres apart) and changes by itself. Reported, its seal closed the way
  // round the wall's end as well.
  const double narrowest_m = 2.0 * (footprint.half_width_m - settings.min_clearance_m);
  const std::vector<geometry::Point> near =
      pointsNear(obstacles, path[0], settings.look_ahead_m + passable_m);
  if (near.empty()) {
    return std::nullopt;
  }
  for (const PathSample& sample : samplePath(path, footprint.front_m, settings.look_ahead_m)) {
    const std::optional<Gap> gap = gapAt(sample, near, passable_m, settings.min_crossing_sine);
    if (gap && gap->width_m < passable_m && gap->width_m >= narrowest_m &&
        between(sample.position, *gap, footprint.half_width_m)) {
      return ImpassableGap{gap->first_post, gap->second_post, gap->width_m, sample.along_m};
    }
  }
  return std::nullopt;
}

std::optional<Doorway> findDoorway(common::Span<const geometry::Point> path,
                                   common::Span<const geometry::Point> obstacles, const Footprint& footprint,
                                   const DoorwaySettings& settings)
{
  if (!settings.enabled || path.size() < 2 || obstacles.empty()) {
    return std::nullopt;
  }
  // Only points that can belong to a gap on the searched stretch or to the run through it.
  const std::vector<geometry::Point> near = pointsNear(
      obstacles, path[0], settings.look_ahead_m + settings.max_width_m + settings.exit_m + footprint.front_m);
  if (near.empty()) {
    return std::nullopt;
  }
  // The narrowest sample of the first stretch of narrow samples along the path.
  std::optional<Gap> narrowest;
  for (const PathSample& sample : samplePath(path, settings.min_ahead_m, settings.look_ahead_m)) {
    const std::optional<Gap> gap = gapAt(sample, near, settings.max_width_m, settings.min_crossing_sine);
    if (!gap || gap->width_m >= settings.max_width_m) {
      if (narrowest) {
        break;
      }
      continue;
    }
    if (!narrowest || gap->width_m < narrowest->width_m) {
      narrowest = gap;
    }
  }
  if (!narrowest || narrowest->width_m < passableWidth(footprint, settings)) {
    return std::nullopt;
  }
  const Run run = bestRun(*narrowest, near, footprint, settings);
  // The search starts min_ahead_m along the path, but the posts found there may be those of a door the
  // vehicle is already in (a side door beside it is fine: its line may be near, the door is not).
  const geometry::Point from_centre = path[0] - run.centre;
  const bool in_door =
      run.heading.dot(from_centre) > -settings.min_ahead_m &&
      std::abs(leftOf(run.heading).dot(from_centre)) < 0.5 * narrowest->width_m + footprint.half_width_m;
  if (run.clearance_m < settings.min_clearance_m || in_door) {
    return std::nullopt;
  }
  Doorway doorway;
  doorway.centre = run.centre;
  doorway.heading = run.heading;
  doorway.width_m = narrowest->width_m;
  doorway.clearance_m = run.clearance_m;
  doorway.first_post = narrowest->first_post;
  doorway.second_post = narrowest->second_post;
  return doorway;
}

}  // namespace ifar::executive
