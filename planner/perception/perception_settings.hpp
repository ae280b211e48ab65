#pragma once
// Settings of the perception stages, read from the `perception:` section of config/planner.yaml; the
// lidar point filter (heights, least range, reflectivity) is the vehicle's (vehicle.yaml `lidar:`).

#include <optional>
#include <string>

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "common/vehicle.hpp"
#include "planner/perception/classification.hpp"

namespace ifar::perception {

struct PerceptionSettings {
  /// Obstacle points lie between these heights above the ground under the vehicle (metres). These four
  /// come from vehicle.yaml `lidar:` (withLidarFilter; the Planner applies its vehicle's).
  double ground_clearance_m = 0.15;
  double vehicle_height_m = 1.2;
  /// Returns closer than this to the sensor are dropped (no-return zeros, the vehicle itself).
  double min_range_m = 0.4;
  /// Points with calibrated reflectivity at or above this are movable (retro-reflective tags read
  /// 101..255 on a VLP-16); used when no detector polygons are given.
  float movable_reflectivity_threshold = 101.0F;
  /// A point's tag is its neighbourhood's when most returns within cells this wide around it disagree
  /// with it (metres; 0 = each point by its own reflectivity; classification.hpp, TagReading).
  double tag_neighbourhood_m = 0.15;
  /// The vehicle-centred local layer: square side and cell size (metres). Twice the lidar's range, so
  /// the layer holds all the sensor can see: where it cuts a remembered wall, the cut corner is out of
  /// sight and behind the vehicle (a cut that moves with the vehicle makes the route flip between ways).
  double layer_size_m = 200.0;
  double cell_size_m = 0.15;
  /// Obstacles grow by this radius before contours are taken: the vehicle's half width.
  double inflation_radius_m = 0.35;
  /// Experimental: move the traced borders the part of the inflation radius that the whole cells of the
  /// disc miss (local_layer.cpp), so an obstacle grows by the radius on average, not by a whole number of
  /// cells (0.30 m for 0.35 m on 0.15 m cells, which leaves every gap the planner sees 0.1 m too wide).
  bool exact_inflation = false;
  /// Douglas-Peucker tolerance for contour simplification (metres).
  double simplify_epsilon_m = 0.1;
  /// Contours (outer borders and holes) enclosing less area than this are dropped (square metres).
  double min_polygon_area_m2 = 0.05;
  /// Keep the background seen in earlier scans in the layer (planner/perception/background_memory.hpp).
  bool remember_background = true;
  /// Gaps in a far wall that no ray went through are filled for the scan (grazing_gap_fill.hpp): returns
  /// of neighbouring rays, the lidar's azimuth step apart (degrees; 0 = off), are joined when a surface
  /// seen at gap_fill_min_incidence_deg or steeper could hold both.
  double gap_fill_azimuth_step_deg = 0.0;
  double gap_fill_min_incidence_deg = 3.0;
  /// Remembered background within this range of the sensor (metres; 0 = never) is forgotten where the
  /// scan's rays pass through it (free_space_view.hpp): a pose that jittered, drifted or jumped drew it
  /// where nothing stands, and a door or corridor it closed would stay closed for good.
  double carve_range_m = 20.0;
  /// ... when the rays go this far past the cell's far side (metres): the lidar's range noise and the
  /// pose's jitter along the ray.
  double carve_margin_m = 0.1;
  /// A remembered cell holds up to this many votes: one more each scan that hits it, one fewer each scan
  /// that sees through it, forgotten at none. A wall seen for long outlasts a few stray rays; a cell one
  /// bad pose drew goes after a scan or two.
  int background_votes = 5;
  /// Within this range of the sensor (metres; 0 = off), remembered background is drawn only where this
  /// scan's rays did not reach: the scan says what stands where it looked.
  double scan_trust_range_m = 8.0;
  /// With no path to the goal left, the remembered background out of the latest scan's sight is forgotten,
  /// at most this many times per goal (each after the vehicle moved): the estimator's drift and jumps draw
  /// remembered walls across doors that no ray of a stopped vehicle passes through.
  int no_path_forget_limit = 3;

  /// Cells along one side of the layer.
  int layerCells() const;
};

/// The first problem with `settings` (a non-positive or non-finite value, an empty height band, a layer
/// of more than 20000 cells a side), naming the field; empty when they are usable.
std::optional<std::string> findSettingsProblem(const PerceptionSettings& settings);

/// planner.yaml `perception:` keys, every one required.
const common::ParameterTable<PerceptionSettings>& perceptionParameters();

/// Reads the `perception` child of `root` (every key required and in range) and rejects unknown keys
/// inside it. Throws common::ConfigError naming file and key. The lidar filter keeps its defaults.
PerceptionSettings loadPerceptionSettings(const common::ConfigNode& root);

/// How the reflectivity classification reads tags under `settings`.
TagReading tagReading(const PerceptionSettings& settings);

/// `settings` with the point filter of the vehicle's lidar.
PerceptionSettings withLidarFilter(PerceptionSettings settings, const common::LidarFilterSettings& lidar);

}  // namespace ifar::perception
