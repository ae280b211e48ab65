#include "planner/perception/perception_settings.hpp"

#include <cmath>
#include <string>

namespace ifar::perception {
namespace {

constexpr int kMaxLayerCells = 20000;

struct KeyProblem {
  const char* key;
  std::string reason;
};

// The gap filling's keys: the step 0 (off) or positive, the incidence above 1.25 steps (the most a join
// spans) and below 90 degrees.
std::optional<KeyProblem> gapFillProblem(const PerceptionSettings& settings)
{
  if (!std::isfinite(settings.gap_fill_azimuth_step_deg) || settings.gap_fill_azimuth_step_deg < 0.0) {
    return KeyProblem{"gap_fill_azimuth_step_deg", "must be 0 (off) or positive, got " +
                                                       std::to_string(settings.gap_fill_azimuth_step_deg)};
  }
  if (settings.gap_fill_azimuth_step_deg > 0.0 &&
      !(settings.gap_fill_min_incidence_deg > 1.25 * settings.gap_fill_azimuth_step_deg &&
        settings.gap_fill_min_incidence_deg < 90.0)) {
    return KeyProblem{"gap_fill_min_incidence_deg",
                      "must be above 1.25 x gap_fill_azimuth_step_deg and below 90, got " +
                          std::to_string(settings.gap_fill_min_incidence_deg)};
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> findSettingsProblem(const PerceptionSettings& settings)
{
  const struct {
    const char* name;
    double value;
  } positive[] = {{"ground_clearance_m", settings.ground_clearance_m},
                  {"vehicle_height_m", settings.vehicle_height_m},
                  {"min_range_m", settings.min_range_m},
                  {"movable_reflectivity_threshold", settings.movable_reflectivity_threshold},
                  {"layer_size_m", settings.layer_size_m},
                  {"cell_size_m", settings.cell_size_m},
                  {"inflation_radius_m", settings.inflation_radius_m},
                  {"simplify_epsilon_m", settings.simplify_epsilon_m},
                  {"min_polygon_area_m2", settings.min_polygon_area_m2}};
  for (const auto& field : positive) {
    if (!std::isfinite(field.value) || field.value <= 0.0) {
      return std::string(field.name) + " must be positive and finite, got " + std::to_string(field.value);
    }
  }
  if (!std::isfinite(settings.carve_range_m) || settings.carve_range_m < 0.0 ||
      !std::isfinite(settings.carve_margin_m) || settings.carve_margin_m < 0.0) {
    return std::string("carve_range_m and carve_margin_m must be 0 or positive");
  }
  if (settings.background_votes < 1) {
    return std::string("background_votes must be at least 1");
  }
  if (settings.vehicle_height_m <= settings.ground_clearance_m) {
    return std::string("vehicle_height_m must be above ground_clearance_m");
  }
  if (const auto problem = gapFillProblem(settings)) {
    return std::string(problem->key) + " " + problem->reason;
  }
  if (settings.cell_size_m > settings.layer_size_m) {
    return std::string("cell_size_m must not exceed layer_size_m");
  }
  if (settings.layer_size_m / settings.cell_size_m > kMaxLayerCells) {
    return std::string("layer_size_m / cell_size_m gives more than 20000 cells per side");
  }
  return std::nullopt;
}

int PerceptionSettings::layerCells() const
{
  return static_cast<int>(std::ceil(layer_size_m / cell_size_m - 1e-9));
}

const common::ParameterTable<PerceptionSettings>& perceptionParameters()
{
  using S = PerceptionSettings;
  using Range = common::ParameterRange;
  static const auto table =
      common::ParameterTable<S>(common::Presence::required)
          .add("layer_size_m", &S::layer_size_m, "m", Range::positive(),
               "side of the square local layer centred on the vehicle: twice the lidar's range, so it holds "
               "all "
               "the sensor can see")
          .add("cell_size_m", &S::cell_size_m, "m", Range::positive(), "raster cell side of the local layer")
          .add("inflation_radius_m", &S::inflation_radius_m, "m", Range::positive(),
               "obstacles grow by this before their outlines are taken: half of vehicle.yaml width_m")
          .add("exact_inflation", &S::exact_inflation, "", Range::any(),
               "experimental, false = off: traced borders are moved the part of inflation_radius_m the "
               "raster's whole cells miss, so obstacles grow by it on average (by 0.30 m, not 0.35, on "
               "0.15 m cells without it)")
          .add("simplify_epsilon_m", &S::simplify_epsilon_m, "m", Range::positive(),
               "Douglas-Peucker tolerance for the obstacle outlines")
          .add("min_polygon_area_m2", &S::min_polygon_area_m2, "m^2", Range::positive(),
               "smaller outlines and enclosed free-space holes are dropped")
          .add(
              "tag_neighbourhood_m", &S::tag_neighbourhood_m, "m", Range::nonNegative(),
              "a return whose tag (reflectivity) disagrees with more than twice as many returns in the cells "
              "this wide around it takes theirs (0 = each by its own): the lidar misses a tag's return now "
              "and then and reads a bright wall as a tag")
          .add("remember_background", &S::remember_background, "", Range::any(),
               "walls seen once stay in the layer after they leave the scan (never movable objects)")
          .add("gap_fill_azimuth_step_deg", &S::gap_fill_azimuth_step_deg, "deg", Range::nonNegative(),
               "experimental, 0 = off: far wall gaps no ray went through are filled, joining returns of rays "
               "this far apart (0.2 for the VLP-16 at 10 Hz)")
          .add("gap_fill_min_incidence_deg", &S::gap_fill_min_incidence_deg, "deg", Range::any(),
               "... when a surface at this angle to the ray or steeper could hold both (above 1.25 steps, "
               "below 90)")
          .add(
              "carve_range_m", &S::carve_range_m, "m", Range::nonNegative(),
              "remembered background this close to the lidar is forgotten where the scans' rays pass through "
              "it (0 = never): a jittered, drifted or jumped pose drew it where nothing stands")
          .add("carve_margin_m", &S::carve_margin_m, "m", Range::nonNegative(),
               "... when the rays go this far past the cell: the lidar's range noise and the pose's jitter")
          .add("background_votes", &S::background_votes, "", Range::atLeast(1),
               "a remembered cell gains a vote each scan that hits it (up to this many) and loses one each "
               "scan that sees through it; forgotten at none")
          .add(
              "scan_trust_range_m", &S::scan_trust_range_m, "m", Range::nonNegative(),
              "within this range of the lidar, remembered background is drawn only where the scan's rays did "
              "not reach (0 = everywhere): where it looked, the scan says what stands, and the memory adds "
              "what "
              "earlier, slightly wrong poses drew beside it")
          .add("no_path_forget_limit", &S::no_path_forget_limit, "", Range::nonNegative(),
               "with no path to the goal left, the remembered background out of the latest scan's sight is "
               "forgotten, at most this many times per goal, each after the vehicle moved 1 m (0 = never): "
               "the estimator's drift draws remembered walls across doors");
  return table;
}

PerceptionSettings loadPerceptionSettings(const common::ConfigNode& root)
{
  const common::ConfigNode node = root.child("perception");
  const PerceptionSettings settings = perceptionParameters().load(node);
  if (const auto problem = gapFillProblem(settings)) {
    node.fail(problem->key, problem->reason);
  }
  if (settings.cell_size_m > settings.layer_size_m) {
    node.fail("cell_size_m", "must not exceed layer_size_m");
  }
  if (settings.layer_size_m / settings.cell_size_m > kMaxLayerCells) {
    node.fail("cell_size_m", "gives more than 20000 cells per side of the layer; use larger cells");
  }
  return settings;
}

TagReading tagReading(const PerceptionSettings& settings)
{
  TagReading reading;
  reading.threshold = settings.movable_reflectivity_threshold;
  reading.neighbourhood_m = settings.tag_neighbourhood_m;
  return reading;
}

PerceptionSettings withLidarFilter(PerceptionSettings settings, const common::LidarFilterSettings& lidar)
{
  settings.ground_clearance_m = lidar.ground_clearance_m;
  settings.vehicle_height_m = lidar.max_height_m;
  settings.min_range_m = lidar.min_range_m;
  settings.movable_reflectivity_threshold = static_cast<float>(lidar.movable_reflectivity_threshold);
  return settings;
}

}  // namespace ifar::perception
