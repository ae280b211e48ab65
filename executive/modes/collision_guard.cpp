#include "executive/modes/collision_guard.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "executive/follower/arc.hpp"
#include "executive/kinematics/angle.hpp"

namespace ifar::executive {
namespace {

/// The guard's comparisons allow this much rounding: distances computed at a slant to the axes are off by
/// it, and a vehicle backing straight along a wall exactly the clearance away was stopped for good.
constexpr double kRoundingM = 1e-4;
/// Resolution of the straight and turning checks: travel between footprint checks, and turn between them.
constexpr double kStraightStepM = 0.02;
constexpr double kTurnStepRad = 0.05;

}  // namespace

CollisionGuard::CollisionGuard(const Footprint& footprint, double clearance_m, double horizon_s,
                               double time_step_s)
    : footprint_(footprint),
      clearance_m_(clearance_m),
      horizon_s_(horizon_s),
      time_step_s_(std::min(time_step_s, horizon_s))
{
}

std::optional<geometry::Point> CollisionGuard::pointInTheWay(
    const geometry::Pose2& pose, const VelocityCommand& command,
    common::Span<const geometry::Point> obstacles) const
{
  if (command.isZero()) {
    return std::nullopt;
  }
  const int steps = static_cast<int>(std::floor(horizon_s_ / time_step_s_ + 1e-9));
  // Points farther than this from the reference point cannot come within the clearance in the horizon.
  const double reach = footprint_.bodyCentre().norm() + footprint_.circumradius() +
                       std::abs(command.linear) * horizon_s_ + clearance_m_;
  for (const geometry::Point& point : obstacles) {
    if ((point - pose.position()).norm() > reach) {
      continue;
    }
    const double distance_now = footprint_.distance(pose, point);
    for (int step = 1; step <= steps; ++step) {
      const geometry::Pose2 ahead = integrateArc(pose, command.linear, command.angular, step * time_step_s_);
      const double distance = footprint_.distance(ahead, point);
      // Only closing in counts, so the vehicle can always back away from something already near.
      if (distance < clearance_m_ - kRoundingM && distance < distance_now - kRoundingM) {
        return point;
      }
    }
  }
  return std::nullopt;
}

bool CollisionGuard::stop(const geometry::Pose2& pose, common::Span<const geometry::Point> obstacles,
                          MotionRequest& request) const
{
  const std::optional<geometry::Point> point = pointInTheWay(pose, request.command, obstacles);
  if (!point) {
    return false;
  }
  request.command = {};
  request.reason +=
      fmt::format(" (stopped: obstacle at ({:.2f}, {:.2f}) in the way)", point->x(), point->y());
  return true;
}

void CollisionGuard::escape(const geometry::Pose2& pose, double linear, common::Span<const double> turn_rates,
                            const std::function<double()>& first_turn_sign,
                            common::Span<const geometry::Point> obstacles, MotionRequest& request) const
{
  const std::string reason = request.reason;
  request.command = {linear, 0.0};
  if (!stop(pose, obstacles, request)) {
    return;
  }
  const std::string stopped = request.reason;
  const double first_sign = first_turn_sign();
  for (const double rate : turn_rates) {
    for (const double sign : {first_sign, -first_sign}) {
      request.reason = reason;
      request.command = {linear, sign * rate};
      if (!stop(pose, obstacles, request)) {
        request.reason +=
            fmt::format(" (on an arc turning {}: straight is blocked)", sign > 0.0 ? "left" : "right");
        return;
      }
    }
  }
  request.reason = stopped;
  request.command = {};
}

double CollisionGuard::freeStraightDistance(const geometry::Pose2& pose, double sign,
                                            common::Span<const geometry::Point> obstacles,
                                            double limit_m) const
{
  const double reach = footprint_.bodyCentre().norm() + footprint_.circumradius() + limit_m + clearance_m_;
  double free_m = limit_m;
  for (const geometry::Point& point : obstacles) {
    if ((point - pose.position()).norm() > reach) {
      continue;
    }
    const double distance_now = footprint_.distance(pose, point);
    for (int step = 1; step * kStraightStepM < free_m + 1e-9; ++step) {
      const double travel = step * kStraightStepM;
      const geometry::Pose2 moved = integrateArc(pose, sign, 0.0, travel);
      const double distance = footprint_.distance(moved, point);
      if (distance < clearance_m_ && distance < distance_now) {
        free_m = travel - kStraightStepM;
        break;
      }
    }
  }
  return std::max(free_m, 0.0);
}

bool CollisionGuard::freeTurn(const geometry::Pose2& pose, double heading,
                              common::Span<const geometry::Point> obstacles, double margin_m) const
{
  const double clearance = clearance_m_ + margin_m;
  const double turn = wrapToPi(heading - pose.heading);
  const int steps = static_cast<int>(std::ceil(std::abs(turn) / kTurnStepRad));
  const double reach = footprint_.bodyCentre().norm() + footprint_.circumradius() + clearance;
  for (const geometry::Point& point : obstacles) {
    if ((point - pose.position()).norm() > reach) {
      continue;
    }
    const double distance_now = footprint_.distance(pose, point);
    for (int step = 1; step <= steps; ++step) {
      const geometry::Pose2 turned{pose.x, pose.y, pose.heading + turn * step / steps};
      const double distance = footprint_.distance(turned, point);
      if (distance < clearance && distance < distance_now) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace ifar::executive
