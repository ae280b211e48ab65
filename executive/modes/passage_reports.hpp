#pragma once
// Telling the planner about passages the vehicle cannot get through (BLOCKED_PASSAGE): a series of stalls
// at one site, or a gap on the path ahead too narrow for the footprint, seen before driving into it.

#include <cstdint>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/span.hpp"
#include "executive/doorway/doorway.hpp"
#include "executive/follower/footprint.hpp"
#include "executive/modes/blocked_passage.hpp"
#include "executive/modes/executive_settings.hpp"

namespace ifar::executive {

class PassageReports {
 public:
  /// `settings.follower.footprint` must be the vehicle's.
  explicit PassageReports(const ExecutiveSettings& settings);

  /// A new goal: stalls toward the last one do not count toward this one.
  void startGoal();

  /// Counts a stall of the vehicle at `position` toward `target`; the blocked_passage_stalls-th at one
  /// site reports the passage as blocked (and starts a new series).
  std::optional<BlockedPassage> countStall(const geometry::Point& position, const geometry::Point& target,
                                           std::int64_t goal_id);
  /// True when following stalled again within stall_site_radius_m of its stall before, and `position` is
  /// that close to where it did.
  bool stalledAgainNear(const geometry::Point& position) const;

  /// True when gaps are looked for on sight at all now (blocked_passage_on_sight, fresh obstacle points,
  /// a push that left an object).
  bool watchesForGaps(bool obstacles_fresh) const;
  /// The impassable gap on `ahead` (the vehicle's position, then the path) to report now: near where a
  /// push left an object when that is the scope, and the same gap at most once per gap_report_repeat_s.
  /// Records it as reported.
  std::optional<ImpassableGap> gapToReport(common::Span<const geometry::Point> ahead,
                                           common::Span<const geometry::Point> obstacles,
                                           std::int64_t now_us);
  /// The report of `gap` seen from `from`, toward the path point `to` beyond it.
  BlockedPassage gapPassage(const ImpassableGap& gap, std::int64_t goal_id, const geometry::Point& from,
                            const geometry::Point& to) const;

  /// Where a push just left its object.
  void rememberPushedObject(const geometry::Point& left_at);

 private:
  /// True when a post of `gap` is within pushed_object.radius_m of where a push left an object.
  bool besidePushedObject(const ImpassableGap& gap) const;

  int stalls_to_report_;
  double site_radius_m_;
  GapReportScope gap_scope_;
  double gap_repeat_s_;
  std::size_t objects_remembered_;
  double object_radius_m_;
  Footprint footprint_;
  DoorwaySettings doorway_;

  geometry::Point stall_site_ = geometry::Point::Zero();         // where the current series of stalls began
  geometry::Point stall_site_target_ = geometry::Point::Zero();  // ... toward what
  int stalls_at_site_ = 0;                                       // stalls of that series
  std::optional<geometry::Point> last_stall_at_;                 // where following last stalled (this goal)
  std::optional<geometry::Point> repeated_stall_at_;  // ... the last within the site radius of the one before
  geometry::Point gap_reported_at_ = geometry::Point::Zero();  // the last impassable gap reported ...
  std::int64_t gap_reported_us_ = -1;                          // ... and when (-1: none yet)
  std::vector<geometry::Point> pushed_objects_left_at_;        // where the last few pushes left their objects
};

}  // namespace ifar::executive
