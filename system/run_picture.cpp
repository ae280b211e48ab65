#include "system/run_picture.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "sim/world/world_geometry.hpp"
#include "viz/canvas.hpp"
#include "viz/world_picture.hpp"

namespace ifar::runner {
namespace {

const viz::Color kTrajectory{220, 30, 30};
const viz::Color kFinalObject{40, 40, 200};
const viz::Color kGoal{30, 90, 220};

}  // namespace

std::string writeRunPicture(const sim::World& world, const common::VehicleSettings& vehicle,
                            const geometry::Point& goal, const RunSummary& summary, const std::string& path)
{
  const viz::WorldPictureStyle style;
  const double resolution = viz::defaultResolution(world);
  viz::Canvas canvas = viz::makeWorldCanvas(world, resolution, style);
  viz::drawWorld(canvas, world, vehicle, style);

  // Final object poses as outlines over the filled start poses, so a push shows as a moved outline.
  for (std::size_t index = 0; index < world.objects.size() && index < summary.final_objects.size(); ++index) {
    canvas.drawPolygon(sim::placedOutline(world.objects[index], summary.final_objects[index]),
                       {std::nullopt, kFinalObject, 2});
  }

  std::vector<geometry::Point> trajectory;
  trajectory.reserve(summary.trajectory.size());
  for (const geometry::Pose2& pose : summary.trajectory) {
    trajectory.push_back(pose.position());
  }
  if (trajectory.size() >= 2) {
    canvas.drawPolyline(trajectory, kTrajectory, 2);
  }
  const double marker = std::max(0.5 * vehicle.width_m, 4.0 * resolution);
  canvas.drawCircle(goal, marker, {std::nullopt, kGoal, 2});

  // The outcome in the legend band, right of the world legend (about 200 pixels wide).
  constexpr std::size_t kMaxReasonCharacters = 60;
  const double band_top = world.bounds_max.y() + style.margin_m + viz::kLegendBandPixels * resolution;
  const double left = world.bounds_min.x() - style.margin_m + 200.0 * resolution;
  const std::string reason = summary.reason.size() > kMaxReasonCharacters
                                 ? summary.reason.substr(0, kMaxReasonCharacters - 3) + "..."
                                 : summary.reason;
  std::vector<std::string> lines = {fmt::format(
      "{}: {:.1f} m in {:.1f} s, {} pushes, {} replans", summary.arrived ? "arrived" : "not arrived",
      summary.distance_m, summary.sim_time_s, summary.pushes, summary.replans)};
  if (!summary.arrived) {
    lines.push_back(reason);
  }
  lines.push_back("red: trajectory, blue outlines: objects at the end");
  for (std::size_t line = 0; line < lines.size(); ++line) {
    canvas.drawText(geometry::Point(left, band_top - (22.0 + 24.0 * static_cast<double>(line)) * resolution),
                    lines[line], viz::Color::gray(20), 11);
  }
  return canvas.writePng(path);
}

}  // namespace ifar::runner
