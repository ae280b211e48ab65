#include "executive/modes/passage_reports.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace ifar::executive {

PassageReports::PassageReports(const ExecutiveSettings& settings)
    : stalls_to_report_(settings.blocked_passage_stalls),
      site_radius_m_(settings.stall_site_radius_m),
      gap_scope_(settings.blocked_passage_on_sight),
      gap_repeat_s_(settings.gap_report_repeat_s),
      objects_remembered_(static_cast<std::size_t>(std::max(1, settings.pushed_objects_remembered))),
      object_radius_m_(settings.pushed_object.radius_m),
      footprint_(settings.follower.footprint),
      doorway_(settings.doorway)
{
}

void PassageReports::startGoal()
{
  stalls_at_site_ = 0;
  last_stall_at_.reset();
  repeated_stall_at_.reset();
}

std::optional<BlockedPassage> PassageReports::countStall(const geometry::Point& position,
                                                         const geometry::Point& target, std::int64_t goal_id)
{
  if (last_stall_at_ && (position - *last_stall_at_).norm() <= site_radius_m_) {
    repeated_stall_at_ = position;
  }
  last_stall_at_ = position;
  if (stalls_at_site_ == 0 || (position - stall_site_).norm() > site_radius_m_ ||
      (target - stall_site_target_).norm() > site_radius_m_) {
    stall_site_ = position;
    stall_site_target_ = target;
    stalls_at_site_ = 0;
  }
  ++stalls_at_site_;
  if (stalls_to_report_ <= 0 || stalls_at_site_ < stalls_to_report_) {
    return std::nullopt;
  }
  // The local planner cannot get the vehicle through what the global path takes for a passage (a gap the
  // planner's inflation leaves open but the footprint does not fit): the planner must route around it.
  BlockedPassage passage;
  passage.goal_id = goal_id;
  passage.from = position;
  passage.to = target;
  passage.stalls = stalls_at_site_;
  passage.text =
      fmt::format("stalled {} times within {:.1f} m of ({:.2f}, {:.2f}) toward ({:.2f}, {:.2f})",
                  stalls_at_site_, site_radius_m_, position.x(), position.y(), target.x(), target.y());
  stalls_at_site_ = 0;
  return passage;
}

bool PassageReports::stalledAgainNear(const geometry::Point& position) const
{
  return repeated_stall_at_ && (position - *repeated_stall_at_).norm() <= site_radius_m_;
}

bool PassageReports::watchesForGaps(bool obstacles_fresh) const
{
  return gap_scope_ != GapReportScope::Off && obstacles_fresh &&
         !(gap_scope_ == GapReportScope::NearPushedObjects && pushed_objects_left_at_.empty());
}

std::optional<ImpassableGap> PassageReports::gapToReport(common::Span<const geometry::Point> ahead,
                                                         common::Span<const geometry::Point> obstacles,
                                                         std::int64_t now_us)
{
  std::optional<ImpassableGap> gap = findImpassableGap(ahead, obstacles, footprint_, doorway_);
  if (!gap) {
    return std::nullopt;
  }
  // Static gaps are left to the follower, which drives round many of them locally (reported, each would
  // be sealed and change the route); a pushed object left across a corridor leaves lanes the planner's
  // inflation shows open, each costing a stall series to report.
  if (gap_scope_ == GapReportScope::NearPushedObjects && !besidePushedObject(*gap)) {
    return std::nullopt;
  }
  // The planner answers within a cycle or two; until then the same path still crosses the gap.
  const geometry::Point middle = 0.5 * (gap->first_post + gap->second_post);
  if (gap_reported_us_ >= 0 && (middle - gap_reported_at_).norm() < site_radius_m_ &&
      static_cast<double>(now_us - gap_reported_us_) * 1e-6 < gap_repeat_s_) {
    return std::nullopt;
  }
  gap_reported_at_ = middle;
  gap_reported_us_ = now_us;
  return gap;
}

BlockedPassage PassageReports::gapPassage(const ImpassableGap& gap, std::int64_t goal_id,
                                          const geometry::Point& from, const geometry::Point& to) const
{
  BlockedPassage passage;
  passage.goal_id = goal_id;
  passage.from = from;
  passage.to = to;
  passage.stalls = 0;
  passage.text = fmt::format(
      "gap of {:.2f} m between ({:.2f}, {:.2f}) and ({:.2f}, {:.2f}), {:.1f} m ahead: narrower than the "
      "vehicle can pass ({:.2f} m)",
      gap.width_m, gap.first_post.x(), gap.first_post.y(), gap.second_post.x(), gap.second_post.y(),
      gap.along_m, passableWidth(footprint_, doorway_));
  return passage;
}

void PassageReports::rememberPushedObject(const geometry::Point& left_at)
{
  // Bounded: only recent pushes matter to the lanes the vehicle is about to drive.
  if (pushed_objects_left_at_.size() >= objects_remembered_) {
    pushed_objects_left_at_.erase(pushed_objects_left_at_.begin());
  }
  pushed_objects_left_at_.push_back(left_at);
}

bool PassageReports::besidePushedObject(const ImpassableGap& gap) const
{
  const double radius = object_radius_m_;
  return std::any_of(pushed_objects_left_at_.begin(), pushed_objects_left_at_.end(),
                     [&gap, radius](const geometry::Point& object) {
                       return (gap.first_post - object).norm() <= radius ||
                              (gap.second_post - object).norm() <= radius;
                     });
}

}  // namespace ifar::executive
