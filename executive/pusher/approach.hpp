#pragma once
// Drives the vehicle to the contact pose of a push: collision-free to a stand-off point behind the
// contact, turn to the push heading, then creep straight forward until the bumper touches (the contact
// pose is reached or the force sensor feels the object).

#include <string>

#include "common/geometry/pose2.hpp"
#include "common/span.hpp"
#include "executive/follower/follower.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/pusher/pose_controller.hpp"

namespace ifar::executive {

struct ApproachSettings {
  double standoff_m = 0.6;            ///< stand-off point this far behind the contact pose
  double standoff_tolerance_m = 0.1;  ///< the stand-off point counts as reached within this
  double heading_tolerance_rad = 0.05;
  double creep_speed = 0.15;          ///< m/s over the last stand-off distance
  double contact_tolerance_m = 0.03;  ///< the contact pose counts as reached within this (along the heading)
  double contact_force_n = 20.0;      ///< a bumper force above this means contact ...
  /// ... within this of the contact pose (along the lane). The object's face is placed to a raster cell
  /// or two; force felt farther back, on the stand-off leg, is something the lidar does not show (a kerb,
  /// a step below the obstacle band) and must not be taken for the object: the creep goes on, and
  /// standing still there gives the contact up as not reached, which keeps the object pushable.
  double force_contact_reach_m = 0.3;
  /// A vehicle stuck on the collision-free leg that stands in the push lane (at most `lane_join_offset_m`
  /// beside its line, `lane_join_m` behind the contact pose, `lane_join_heading_rad` off its heading)
  /// creeps along the lane instead (joinLane): in a corridor too narrow to turn in, the leg's last
  /// decimetres squeeze and turn it across.
  double lane_join_m = 1.6;
  double lane_join_offset_m = 0.2;
  double lane_join_heading_rad = 0.35;
  /// False: the collision-free leg passes through the stand-off point at speed instead of stopping there
  /// (a doorway run, which tracks its lane from a heading within heading_tolerance_rad while moving).
  bool stop_at_standoff = true;
  /// The collision-free leg squeezes down to this clearance when stuck at the follower's (followSqueezing).
  double squeeze_clearance_m = 0.05;
  /// Aligning at the stand-off point turns on the spot; when the guard would stop that turn, the executive
  /// backs straight up at most this far per approach until it is free: a wall square ahead needs 0.2 m at
  /// most (the front corners sweep the footprint's 0.57 m circumradius, the bumper is 0.45 m ahead), a
  /// slanted one or a corner more.
  double align_backup_m = 0.5;
  /// ... until the turn keeps this much more than the guard clearance: the guard steps the turn otherwise
  /// than the free-turn test and would stop one that only just clears.
  double align_turn_margin_m = 0.03;
  PoseControllerSettings control;
};

enum class ApproachPhase { ToStandoff, Align, Creep, Done };

const char* approachPhaseName(ApproachPhase phase);

struct ApproachStep {
  VelocityCommand command;
  ApproachPhase phase = ApproachPhase::ToStandoff;
  std::string reason;
};

class Approach {
 public:
  Approach() = default;
  /// Starts a new approach to `contact`. When the vehicle already stands in the lane behind the contact
  /// (within the stand-off distance and tolerance, facing it), it skips the collision-free leg.
  void begin(const geometry::Pose2& contact, const geometry::Pose2& pose, const ApproachSettings& settings);
  /// On the collision-free leg, when the vehicle stands in the push lane (ApproachSettings::lane_join_m):
  /// the leg is left for the creep, whose lane tracker takes out the offset and heading error while moving
  /// (no turn on the spot). True when it was (the caller says when: the leg is stuck).
  bool joinLane(const geometry::Pose2& pose, const ApproachSettings& settings);

  /// One control cycle. `obstacles` are used for the collision-free leg only: near the object the
  /// vehicle must come closer than any clearance.
  ApproachStep step(const geometry::Pose2& pose, double force_n,
                    common::Span<const geometry::Point> obstacles, const ApproachSettings& settings,
                    const FollowerSettings& follower, const DifferentialDrive& drive);

  ApproachPhase phase() const { return phase_; }
  const geometry::Pose2& contact() const { return contact_; }

 private:
  geometry::Point standoffPoint(const ApproachSettings& settings) const;

  geometry::Pose2 contact_;
  ApproachPhase phase_ = ApproachPhase::Done;
};

}  // namespace ifar::executive
