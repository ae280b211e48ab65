#pragma once
// Executes a push plan once the bumper touches the object (paper section VII.B, "InteractivePlanner"):
// tracks each push primitive's arc with feedback from the pose, backs off and re-approaches for a
// contact switch, and backs away from the object at the end so the follower can take over.

#include <cstddef>
#include <string>

#include "common/geometry/pose2.hpp"
#include "common/span.hpp"
#include "executive/follower/follower.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/pusher/approach.hpp"
#include "executive/pusher/pose_controller.hpp"
#include "executive/pusher/push_plan.hpp"

namespace ifar::executive {

struct PushTrackerSettings {
  PoseControllerSettings control;
  double end_tolerance_s = 0.05;  ///< a primitive is done when the vehicle is this close (in time) to its end
  double backoff_m = 0.4;         ///< reverse this far before a contact switch
  double release_m = 0.3;         ///< reverse this far after the last primitive
  double reverse_speed = 0.2;     ///< m/s while backing off
};

enum class PushPhase { Pushing, BackingOff, Switching, Releasing, Finished };

const char* pushPhaseName(PushPhase phase);

struct PushStep {
  VelocityCommand command;
  PushPhase phase = PushPhase::Finished;
  std::size_t control_index = 0;
  /// True while the bumper should be on the object (pushing), so force readings mean something.
  bool expects_contact = false;
  std::string reason;
};

class PushTracker {
 public:
  PushTracker() = default;
  /// Starts executing `plan` (copied) with the vehicle at its contact pose.
  void begin(const PushPlan& plan);

  PushStep step(const geometry::Pose2& pose, double force_n, common::Span<const geometry::Point> obstacles,
                const PushTrackerSettings& settings, const ApproachSettings& approach,
                const FollowerSettings& follower, const DifferentialDrive& drive);

  bool finished() const { return phase_ == PushPhase::Finished; }
  const PushPlan& plan() const { return plan_; }

  /// Where along the current primitive's arc the vehicle is (seconds from its start), for tests and logs.
  double progressTime() const { return progress_s_; }

 private:
  geometry::Pose2 stepStart(std::size_t index) const;
  void startControl(std::size_t index, const geometry::Pose2& pose);

  PushPlan plan_;
  std::size_t index_ = 0;
  PushPhase phase_ = PushPhase::Finished;
  double progress_s_ = 0.0;
  geometry::Point reverse_start_ = geometry::Point::Zero();
  Approach approach_;
};

/// How far along the arc from `start` with (linear, angular) the pose lies, in seconds, searched near
/// `near_s` (so arcs turning more than half a circle stay unambiguous). Not clamped.
double projectOntoArc(const geometry::Pose2& start, double linear, double angular, double near_s,
                      const geometry::Pose2& pose);

}  // namespace ifar::executive
