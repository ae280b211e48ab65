#include "system/graph_picture.hpp"

#include <fmt/format.h>

#include "planner/node/planner_messages.hpp"
#include "sim/world/world_geometry.hpp"

namespace ifar::runner {

void GraphPicture::observe(const FrameView& frame)
{
  if (at_s_ && (graph_ || frame.sim_time_s < *at_s_)) {
    return;
  }
  planner::PlannerMessages messages = planner::toMessages(frame.planner, frame.result, 0);
  graph_ = std::move(messages.graph);
  path_ = std::move(messages.path);
  trajectory_.clear();
  trajectory_.reserve(frame.trajectory.size());
  for (const geometry::Pose2& pose : frame.trajectory) {
    trajectory_.push_back(pose.position());
  }
  object_poses_.clear();
  for (const sim::physics::BodyState& object : frame.objects) {
    object_poses_.push_back(object.pose);
  }
  kept_time_s_ = frame.sim_time_s;
}

std::string GraphPicture::writePng(const std::string& path, const viz::RenderOptions& options) const
{
  if (!graph_) {
    return at_s_ ? fmt::format("{}: no planner frame at or after {:.1f} s of simulated time", path, *at_s_)
                 : fmt::format("{}: the run had no planner frame", path);
  }
  viz::RunOverlay overlay;
  overlay.trajectory = trajectory_;
  if (path_) {
    for (const push_plan_t& plan : path_->push_plans) {
      overlay.push_plans.push_back(viz::pushPlanPoints(plan));
    }
  }
  for (const sim::StaticObstacle& obstacle : world_.obstacles) {
    overlay.truth.push_back(obstacle.outline);
  }
  for (std::size_t index = 0; index < world_.objects.size() && index < object_poses_.size(); ++index) {
    overlay.truth.push_back(sim::placedOutline(world_.objects[index], object_poses_[index]));
  }
  return viz::renderGraph(*graph_, path_, options, overlay).writePng(path);
}

}  // namespace ifar::runner
