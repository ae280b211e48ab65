#pragma once
// The whole perception frame: sensor points and vehicle motion in, classified world-frame obstacle
// polygons of the local layer out, with counts and per-stage timings for the planner's status.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/span.hpp"
#include "planner/perception/free_space_view.hpp"
#include "planner/perception/local_layer.hpp"
#include "planner/perception/perception_settings.hpp"
#include "planner/perception/sensor_point.hpp"

namespace ifar::perception {

struct PerceptionInput {
  common::Span<const SensorPoint> points;  // one revolution; only used during the call
  SensorMount mount = SensorMount::Identity();
  ScanMotion motion;
  /// Movable-object outlines from an external detector (world frame). When present (even empty),
  /// they decide what is movable instead of the reflectivity threshold.
  std::optional<std::vector<geometry::Polygon>> detector_polygons;
  /// Background seen in earlier scans (world frame, e.g. BackgroundMemory cell centres): drawn into the
  /// layer with this scan's background points. Only used during the call.
  common::Span<const geometry::Point> remembered_background;
  /// Background known otherwise (passages sealed after stalls, a prior map): drawn as it is.
  common::Span<const geometry::Point> kept_background;
};

enum class PerceptionStatus {
  Ok,                // polygons built from obstacle points
  EmptyScan,         // the scan held no points at all: no polygons
  NoObstaclePoints,  // points, but none between ground clearance and vehicle height: no polygons
  InvalidMotion,     // non-finite or improper pose or duration: frame rejected, no polygons
  InvalidSettings,   // settings fail findSettingsProblem: frame rejected, no polygons
};

const char* toString(PerceptionStatus status);

struct PerceptionStats {
  std::size_t input_points = 0;
  std::size_t non_finite_points = 0;
  std::size_t too_close_points = 0;
  std::size_t outside_height_band_points = 0;
  std::size_t background_points = 0;
  std::size_t movable_points = 0;
  std::size_t gap_fill_points = 0;  // joined across grazing gaps (grazing_gap_fill.hpp), this scan only
  std::size_t points_outside_layer = 0;
  std::size_t dropped_contours = 0;
  double compensation_ms = 0.0;
  double filter_ms = 0.0;
  double classification_ms = 0.0;
  double layer_ms = 0.0;
  double total_ms = 0.0;
};

struct PerceptionResult {
  PerceptionStatus status = PerceptionStatus::Ok;
  std::string message;  // human-readable summary, names the reason when the status is not Ok
  LocalLayer layer;     // centred on the vehicle's position at the end of the scan
  std::vector<geometry::Point> observed_background;  // this scan's background obstacle points (world)
  std::vector<geometry::Point> observed_movable;     // and its movable ones
  std::vector<float> observed_background_heights_m;  // height above the ground of each, as observed
  std::vector<float> observed_movable_heights_m;
  /// Where this scan's rays went through the height band (BackgroundMemory::forgetSeenThrough); empty
  /// unless settings.carve_range_m > 0 and the background is remembered.
  FreeSpaceView free_space;
  PerceptionStats stats;
};

PerceptionResult runPerception(const PerceptionInput& input, const PerceptionSettings& settings);

}  // namespace ifar::perception
