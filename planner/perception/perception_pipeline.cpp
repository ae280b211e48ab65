#include "planner/perception/perception_pipeline.hpp"

#include <chrono>
#include <vector>

#include "common/geometry/angle.hpp"
#include "planner/perception/classification.hpp"
#include "planner/perception/grazing_gap_fill.hpp"
#include "planner/perception/height_filter.hpp"
#include "planner/perception/motion_compensation.hpp"

namespace ifar::perception {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

GrazingGapSettings grazingGapSettings(const PerceptionSettings& settings)
{
  GrazingGapSettings gaps;
  gaps.azimuth_step_rad = geometry::radiansFromDegrees(settings.gap_fill_azimuth_step_deg);
  gaps.min_incidence_rad = geometry::radiansFromDegrees(settings.gap_fill_min_incidence_deg);
  gaps.spacing_m = 0.5 * settings.cell_size_m;
  return gaps;
}

FreeSpaceSettings freeSpaceSettings(const PerceptionSettings& settings)
{
  FreeSpaceSettings free_space;
  free_space.ground_clearance_m = settings.ground_clearance_m;
  free_space.vehicle_height_m = settings.vehicle_height_m;
  free_space.min_range_m = settings.min_range_m;
  free_space.margin_m = settings.carve_margin_m;
  return free_space;
}

/// Appends the remembered cells to `background`, except those within scan_trust_range_m that this scan's
/// rays reached: there the scan itself says what stands, and what the memory adds is what earlier poses,
/// each a little off, drew beside it (a jamb's returns a cell into the doorway, one scan in three).
void appendRememberedOutOfView(common::Span<const geometry::Point> remembered, const FreeSpaceView& view,
                               const PerceptionSettings& settings, std::vector<geometry::Point>& background)
{
  const double range = settings.scan_trust_range_m;
  if (!(range > 0.0) || view.empty()) {
    background.insert(background.end(), remembered.begin(), remembered.end());
    return;
  }
  for (const geometry::Point& cell : remembered) {
    if ((cell - view.origin()).squaredNorm() < range * range && view.reaches(cell, settings.cell_size_m)) {
      continue;
    }
    background.push_back(cell);
  }
}

}  // namespace

const char* toString(PerceptionStatus status)
{
  switch (status) {
    case PerceptionStatus::Ok:
      return "ok";
    case PerceptionStatus::EmptyScan:
      return "empty scan";
    case PerceptionStatus::NoObstaclePoints:
      return "no obstacle points";
    case PerceptionStatus::InvalidMotion:
      return "invalid motion";
    case PerceptionStatus::InvalidSettings:
      return "invalid settings";
  }
  return "unknown";
}

PerceptionResult runPerception(const PerceptionInput& input, const PerceptionSettings& settings)
{
  const Clock::time_point frame_start = Clock::now();
  PerceptionResult result;
  result.stats.input_points = input.points.size();
  if (const auto problem = findSettingsProblem(settings)) {
    result.status = PerceptionStatus::InvalidSettings;
    result.message = "perception settings: " + *problem;
    return result;
  }
  if (!isValidMotion(input.motion) || !input.mount.matrix().allFinite()) {
    result.status = PerceptionStatus::InvalidMotion;
    result.message = "scan motion or sensor mount is not a finite rigid transform with duration >= 0";
    return result;
  }
  const auto vehicle_position = input.motion.vehicle_at_end.translation();
  const geometry::Point centre(vehicle_position.x(), vehicle_position.y());

  Clock::time_point stage_start = Clock::now();
  const std::vector<WorldPoint> world_points = compensateMotion(input.points, input.mount, input.motion);
  result.stats.compensation_ms = millisecondsSince(stage_start);

  stage_start = Clock::now();
  const HeightFilterResult filtered = filterObstaclePoints(world_points, settings);
  result.stats.filter_ms = millisecondsSince(stage_start);
  result.stats.non_finite_points = filtered.counts.non_finite;
  result.stats.too_close_points = filtered.counts.too_close;
  result.stats.outside_height_band_points = filtered.counts.outside_height_band;

  stage_start = Clock::now();
  ClassifiedPoints classified = input.detector_polygons
                                    ? classifyByDetector(filtered.obstacle_points, *input.detector_polygons)
                                    : classifyByReflectivity(filtered.obstacle_points, tagReading(settings));
  result.stats.classification_ms = millisecondsSince(stage_start);
  result.stats.background_points = classified.background.size();
  result.stats.movable_points = classified.movable.size();

  result.observed_background = classified.background;
  result.observed_movable = classified.movable;
  result.observed_background_heights_m = classified.background_heights_m;
  result.observed_movable_heights_m = classified.movable_heights_m;
  // Filled gaps hold for this scan only: the memory keeps what rays hit, so a passage a later, nearer scan
  // sees through is not closed for good.
  const Eigen::Vector3d sensor = (input.motion.vehicle_at_end * input.mount).translation();
  if (settings.carve_range_m > 0.0 && settings.remember_background) {
    result.free_space =
        FreeSpaceView(world_points, geometry::Point(sensor.x(), sensor.y()), freeSpaceSettings(settings));
  }
  const std::vector<geometry::Point> gap_fill =
      fillGrazingGaps(classified.background, classified.movable, geometry::Point(sensor.x(), sensor.y()),
                      grazingGapSettings(settings));
  result.stats.gap_fill_points = gap_fill.size();
  classified.background.insert(classified.background.end(), gap_fill.begin(), gap_fill.end());
  appendRememberedOutOfView(input.remembered_background, result.free_space, settings, classified.background);
  classified.background.insert(classified.background.end(), input.kept_background.begin(),
                               input.kept_background.end());

  stage_start = Clock::now();
  result.layer = buildLocalLayer(classified, centre, settings);
  result.stats.layer_ms = millisecondsSince(stage_start);
  result.stats.points_outside_layer = result.layer.points_outside_layer;
  result.stats.dropped_contours = result.layer.dropped_contours;

  if (input.points.empty()) {
    result.status = PerceptionStatus::EmptyScan;
    result.message = "empty scan: no points, no polygons";
  } else if (filtered.obstacle_points.empty()) {
    result.status = PerceptionStatus::NoObstaclePoints;
    result.message = "no obstacle points between ground clearance and vehicle height, no polygons";
  } else {
    result.status = PerceptionStatus::Ok;
    result.message = std::to_string(result.layer.polygons.size()) + " polygons";
  }
  if (filtered.counts.non_finite > 0) {
    result.message += "; dropped " + std::to_string(filtered.counts.non_finite) + " non-finite points";
  }
  result.stats.total_ms = millisecondsSince(frame_start);
  return result;
}

}  // namespace ifar::perception
