#include "executive/follower/follower.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "executive/follower/arc.hpp"
#include "executive/follower/navigation_field.hpp"
#include "executive/follower/obstacle_grid.hpp"
#include "executive/kinematics/angle.hpp"

namespace ifar::executive {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Smallest distance from the footprint at `pose` to a point near it (capped at `search_radius`).
double clearanceAt(const geometry::Pose2& pose, const ObstacleGrid& grid, const Footprint& footprint,
                   double search_radius)
{
  const double cosine = std::cos(pose.heading);
  const double sine = std::sin(pose.heading);
  const geometry::Point body_centre = footprint.bodyCentre();
  const geometry::Point centre(pose.x + cosine * body_centre.x() - sine * body_centre.y(),
                               pose.y + sine * body_centre.x() + cosine * body_centre.y());
  // Squared distances pick the nearest point and one hypot measures it: a hypot per point was most of
  // the follower's cycle.
  double nearest_squared = kInfinity;
  geometry::Point nearest_body = geometry::Point::Zero();
  grid.forEachNear(centre, footprint.circumradius() + search_radius, [&](const geometry::Point& point) {
    const double dx = point.x() - pose.x;
    const double dy = point.y() - pose.y;
    const geometry::Point body(cosine * dx + sine * dy, -sine * dx + cosine * dy);
    const double squared = footprint.squaredDistanceFromBody(body);
    if (squared < nearest_squared) {
      nearest_squared = squared;
      nearest_body = body;
    }
  });
  return nearest_squared < kInfinity ? std::min(search_radius, footprint.distanceFromBody(nearest_body))
                                     : search_radius;
}

double headingError(const geometry::Pose2& pose, const geometry::Point& target)
{
  const double bearing = std::atan2(target.y() - pose.y, target.x() - pose.x);
  return std::abs(wrapToPi(bearing - pose.heading));
}

/// Top speed of the arcs toward `target`. Near a target to stop at it follows a constant-deceleration
/// braking curve that reaches zero at the tolerance's edge (not a linear ramp, which creeps over the last
/// metre), floored at a quarter of the top speed so the vehicle still gets there.
double topSpeed(const geometry::Pose2& pose, const geometry::Point& target, bool stop_at_target,
                const FollowerSettings& settings, const DifferentialDrive& drive)
{
  double top_speed = std::min(settings.max_linear_velocity, drive.maxLinearVelocity());
  if (stop_at_target && settings.slow_down_distance_m > 0.0) {
    const double remaining = std::max(0.0, (target - pose.position()).norm() - settings.goal_tolerance_m);
    top_speed *= std::clamp(std::sqrt(remaining / settings.slow_down_distance_m), 0.25, 1.0);
  }
  return top_speed;
}

/// The cost-to-go toward `target` in a window that holds every arc of length `reach`.
NavigationField navigationField(const geometry::Pose2& pose, const geometry::Point& target,
                                bool stop_at_target, common::Span<const geometry::Point> obstacles,
                                const FollowerSettings& settings, double reach)
{
  const double start_distance = (target - pose.position()).norm();
  const double window =
      std::clamp(start_distance + 1.0, reach + 2.0 * settings.footprint.circumradius(),
                 std::max(settings.navigation_range_m, reach + 2.0 * settings.footprint.circumradius()));
  NavigationFieldShape shape;
  shape.half_size_m = window;
  shape.cell_size_m = settings.navigation_cell_m;
  shape.blocked_m = settings.footprint.half_width_m;
  shape.comfort_m = settings.footprint.half_width_m + settings.clearance_cap_m;
  shape.proximity_weight = settings.navigation_proximity_weight;
  shape.open_around_target = stop_at_target;
  return NavigationField(obstacles, pose.position(), target, shape);
}

/// What one follow() cycle scores every arc against.
struct ArcScoring {
  const geometry::Pose2& pose;
  const geometry::Point& target;
  const ObstacleGrid& grid;
  const NavigationField& field;
  const FollowerSettings& settings;
  double start_distance;  ///< straight-line distance to the target
  double start_cost;      ///< cost-to-go at the pose
  double search_radius;   ///< clearances are measured up to this
  double margin;          ///< an arc closer than this to a point is not free
  double reach;           ///< the longest arc's length
  int steps;              ///< footprint checks along an arc
};

/// A free arc's worth.
struct ScoredArc {
  double score = 0.0;
  double clearance_m = 0.0;
  double gain_m = 0.0;  ///< how much it lowers the cost-to-go
};

/// How well the heading at `end` faces the way the cost-to-go falls (through the door, round the box), not
/// the straight line to the target: turning on the spot gains no progress, so this is what tells the good
/// turn apart. Within the sampling radius of the target the circle reaches past it: face the target itself.
double facingScore(const geometry::Pose2& end, bool reached, const ArcScoring& scoring)
{
  const geometry::Point& target = scoring.target;
  const double radius = scoring.settings.descent_radius_m;
  double facing = 1.0;
  if (!reached && (target - end.position()).norm() <= radius) {
    facing = 1.0 - headingError(end, target) / kPi;
  } else if (!reached) {
    const std::optional<double> descent = scoring.field.descentDirection(end.position(), radius);
    facing = 1.0 - (descent ? std::abs(wrapToPi(*descent - end.heading)) : headingError(end, target)) / kPi;
  }
  return facing;
}

/// The arc's score, or none when its footprint comes closer than the margin to a point.
std::optional<ScoredArc> scoreArc(const ArcScoring& scoring, const VelocityCommand& arc)
{
  const FollowerSettings& settings = scoring.settings;
  const geometry::Point& target = scoring.target;
  double arc_clearance = scoring.search_radius;
  geometry::Pose2 end = scoring.pose;
  bool reached = false;
  for (int step = 1; step <= scoring.steps && !reached; ++step) {
    const geometry::Pose2 sample =
        integrateArc(scoring.pose, arc.linear, arc.angular, step * settings.time_step_s);
    const double clearance = clearanceAt(sample, scoring.grid, settings.footprint, scoring.search_radius);
    if (clearance < scoring.margin || clearance <= 0.0) {
      return std::nullopt;
    }
    arc_clearance = std::min(arc_clearance, clearance);
    end = sample;
    reached = (target - sample.position()).norm() <= settings.goal_tolerance_m;
  }
  // Progress: how much the arc lowers the cost-to-go (straight-line distance where the field has none).
  const double end_cost = scoring.field.value(end.position());
  double gain = scoring.start_distance - (target - end.position()).norm();
  if (std::isfinite(scoring.start_cost)) {
    gain = std::isfinite(end_cost) ? scoring.start_cost - end_cost : gain - 1.0;
  }
  const double progress = gain / std::max(scoring.reach, 1e-3);
  const double facing = facingScore(end, reached, scoring);
  ScoredArc scored;
  scored.score = settings.progress_weight * progress + settings.heading_weight * facing +
                 settings.clearance_weight * std::min(arc_clearance, settings.clearance_cap_m) /
                     std::max(settings.clearance_cap_m, 1e-3);
  scored.clearance_m = arc_clearance;
  scored.gain_m = gain;
  return scored;
}

/// Samples the fan of arcs (forward speeds up to `top_speed`, plus turning on the spot, times the turn
/// rates; with `top_speed` 0 only the turns on the spot) and sets `result`'s command, clearance and
/// progress to the best free one; counts the arcs.
void pickArc(const ArcScoring& scoring, double top_speed, const DifferentialDrive& drive,
             FollowerResult& result)
{
  const int linear_samples = top_speed > 0.0 ? std::max(1, scoring.settings.linear_samples) : 0;
  const int angular_samples = std::max(2, scoring.settings.angular_samples);
  double best_score = -kInfinity;
  for (int linear_index = 0; linear_index <= linear_samples; ++linear_index) {
    for (int angular_index = 0; angular_index < angular_samples; ++angular_index) {
      const double fraction = -1.0 + 2.0 * angular_index / (angular_samples - 1);
      VelocityCommand arc{linear_samples > 0 ? top_speed * linear_index / linear_samples : 0.0,
                          drive.maxAngularVelocity() * fraction};
      if (arc.linear == 0.0 && std::abs(arc.angular) < 1e-9) {
        continue;
      }
      arc = drive.limitSpeed(arc);
      ++result.arcs;
      const std::optional<ScoredArc> scored = scoreArc(scoring, arc);
      if (!scored) {
        continue;
      }
      ++result.free_arcs;
      if (scored->score > best_score) {
        best_score = scored->score;
        result.command = arc;
        result.clearance_m = scored->clearance_m;
        result.progress_m = scored->gain_m;
      }
    }
  }
}

/// The forward speed allowed facing `heading_error` (radians, 0..pi) off the way on (see
/// FollowerSettings::turn_in_place_rad).
double headingSpeedCap(double top_speed, double heading_error, const FollowerSettings& settings)
{
  if (settings.turn_in_place_rad <= 0.0) {
    return top_speed;
  }
  // Small corrections keep full speed: the cap starts at a third of the pivot angle.
  const double free_error = settings.turn_in_place_rad / 3.0;
  return top_speed *
         std::clamp((settings.turn_in_place_rad - heading_error) / (settings.turn_in_place_rad - free_error),
                    0.0, 1.0);
}

/// How far the heading is off the way the cost-to-go falls at the pose, signed (counter-clockwise
/// positive): off the target's bearing when the target is within the sampling circle, or the field has no
/// way there.
double headingErrorToTheWayOn(const geometry::Pose2& pose, const geometry::Point& target,
                              const NavigationField& field, const FollowerSettings& settings)
{
  if ((target - pose.position()).norm() > settings.descent_radius_m) {
    if (const std::optional<double> descent =
            field.descentDirection(pose.position(), settings.descent_radius_m)) {
      return wrapToPi(*descent - pose.heading);
    }
  }
  return wrapToPi(std::atan2(target.y() - pose.y, target.x() - pose.x) - pose.heading);
}

}  // namespace

const char* followerStatusName(FollowerStatus status)
{
  switch (status) {
    case FollowerStatus::Moving:
      return "moving";
    case FollowerStatus::Arrived:
      return "arrived";
    case FollowerStatus::Blocked:
      return "blocked";
    case FollowerStatus::InvalidInput:
      return "invalid input";
  }
  return "unknown";
}

FollowerResult follow(const geometry::Pose2& pose, const geometry::Point& target, bool stop_at_target,
                      common::Span<const geometry::Point> obstacles, const FollowerSettings& settings,
                      const DifferentialDrive& drive)
{
  FollowerResult result;
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.heading) ||
      !target.allFinite()) {
    result.status = FollowerStatus::InvalidInput;
    result.reason = "follower: pose or target is not finite";
    return result;
  }
  const double start_distance = (target - pose.position()).norm();
  if (start_distance <= settings.goal_tolerance_m) {
    result.status = FollowerStatus::Arrived;
    result.reason = fmt::format("target reached ({:.2f} m away)", start_distance);
    return result;
  }

  const double top_speed = topSpeed(pose, target, stop_at_target, settings, drive);
  const double reach = top_speed * settings.horizon_s;
  const double search_radius = std::max(settings.clearance_cap_m, settings.clearance_m);
  const ObstacleGrid grid(
      obstacles, pose.position(),
      reach + settings.footprint.circumradius() * 2.0 + search_radius + settings.cell_size_m,
      settings.cell_size_m);

  const NavigationField field = navigationField(pose, target, stop_at_target, obstacles, settings, reach);
  const double start_cost = field.value(pose.position());

  // Already closer than the clearance (after a push, or a point that appeared close): accept arcs that do
  // not come closer than now, so the vehicle can still leave.
  const double start_clearance = clearanceAt(pose, grid, settings.footprint, search_radius);
  const double margin = std::min(settings.clearance_m, start_clearance);
  const int steps = std::max(1, static_cast<int>(std::ceil(settings.horizon_s / settings.time_step_s)));
  const ArcScoring scoring{pose,       target,        grid,   field, settings, start_distance,
                           start_cost, search_radius, margin, reach, steps};
  // Facing off the way on, slower (down to turning on the spot); when that does not turn the vehicle
  // toward the way on (the turn is blocked: a post beside the rear, a box ahead), the whole fan.
  const double heading_error = headingErrorToTheWayOn(pose, target, field, settings);
  const double capped_speed = headingSpeedCap(top_speed, std::abs(heading_error), settings);
  pickArc(scoring, capped_speed, drive, result);
  // A turn counts when it gets a good part of the way round within the horizon: a slow turn that is all
  // the room allows (blocked a few degrees on) is no way to turn.
  constexpr double kUsefulTurnRad = 0.5;
  const bool turns_toward = result.free_arcs > 0 && result.command.angular * heading_error > 0.0 &&
                            std::abs(result.command.angular) * settings.horizon_s >=
                                std::min(std::abs(heading_error), kUsefulTurnRad);
  if (capped_speed < top_speed && !turns_toward) {
    result = FollowerResult{};
    pickArc(scoring, top_speed, drive, result);
  }

  if (result.free_arcs == 0) {
    result.status = FollowerStatus::Blocked;
    result.command = {};
    result.clearance_m = start_clearance;
    result.reason = fmt::format("blocked: none of {} arcs is collision-free (clearance {:.2f} m)",
                                result.arcs, start_clearance);
    return result;
  }
  result.status = FollowerStatus::Moving;
  result.reason = fmt::format("following: {:.2f} m to target, {} of {} arcs free", start_distance,
                              result.free_arcs, result.arcs);
  return result;
}

FollowerResult followSqueezing(const geometry::Pose2& pose, const geometry::Point& target,
                               bool stop_at_target, common::Span<const geometry::Point> obstacles,
                               const FollowerSettings& settings, double squeeze_clearance_m,
                               const DifferentialDrive& drive)
{
  constexpr double kNoProgressM = 0.01;
  FollowerResult result = follow(pose, target, stop_at_target, obstacles, settings, drive);
  const bool stuck = result.status == FollowerStatus::Blocked ||
                     (result.status == FollowerStatus::Moving && result.progress_m <= kNoProgressM);
  if (!stuck || !(squeeze_clearance_m < settings.clearance_m)) {
    return result;
  }
  FollowerSettings squeezed = settings;
  squeezed.clearance_m = squeeze_clearance_m;
  FollowerResult retry = follow(pose, target, stop_at_target, obstacles, squeezed, drive);
  if (retry.status == FollowerStatus::Moving &&
      (result.status == FollowerStatus::Blocked || retry.progress_m > result.progress_m + kNoProgressM)) {
    retry.reason += fmt::format(" (squeezing: clearance {:.2f} m)", squeeze_clearance_m);
    return retry;
  }
  return result;
}

FollowerResult followReversing(const geometry::Pose2& pose, const geometry::Point& target,
                               common::Span<const geometry::Point> obstacles,
                               const FollowerSettings& settings, double squeeze_clearance_m,
                               double reverse_speed, const DifferentialDrive& drive)
{
  // A differential drive turned round moves the same way with (-v, omega): mirror the pose and the
  // footprint, plan forward, and hand back the command negated.
  const geometry::Pose2 turned{pose.x, pose.y, wrapToPi(pose.heading + kPi)};
  FollowerSettings rear_first = settings;
  std::swap(rear_first.footprint.front_m, rear_first.footprint.rear_m);
  rear_first.max_linear_velocity = std::min(settings.max_linear_velocity, reverse_speed);
  FollowerResult result =
      followSqueezing(turned, target, false, obstacles, rear_first, squeeze_clearance_m, drive);
  result.command.linear = -result.command.linear;
  result.reason = "reversing: " + result.reason;
  return result;
}

std::optional<double> facingDirection(const geometry::Pose2& pose, const geometry::Point& target,
                                      bool stop_at_target, common::Span<const geometry::Point> obstacles,
                                      const FollowerSettings& settings, const DifferentialDrive& drive)
{
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !target.allFinite()) {
    return std::nullopt;
  }
  if ((target - pose.position()).norm() <= settings.descent_radius_m) {
    return std::atan2(target.y() - pose.y, target.x() - pose.x);
  }
  const double reach = topSpeed(pose, target, stop_at_target, settings, drive) * settings.horizon_s;
  return navigationField(pose, target, stop_at_target, obstacles, settings, reach)
      .descentDirection(pose.position(), settings.descent_radius_m);
}

}  // namespace ifar::executive
