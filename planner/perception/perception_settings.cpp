#include "planner/perception/perception_settings.hpp"

#include <cmath>
#include <string>

namespace ifar::perception {
namespace {

double requirePositive(const common::ConfigNode& node, const std::string& key)
{
  const auto value = node.required<double>(key);
  if (!std::isfinite(value) || value <= 0.0) {
    node.fail(key, "must be a positive number of the stated unit, got " + std::to_string(value));
  }
  return value;
}

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

PerceptionSettings loadPerceptionSettings(const common::ConfigNode& root)
{
  const common::ConfigNode node = root.child("perception");
  PerceptionSettings settings;
  settings.ground_clearance_m = requirePositive(node, "ground_clearance_m");
  settings.vehicle_height_m = requirePositive(node, "vehicle_height_m");
  settings.min_range_m = requirePositive(node, "min_range_m");
  settings.movable_reflectivity_threshold =
      static_cast<float>(requirePositive(node, "movable_reflectivity_threshold"));
  settings.layer_size_m = requirePositive(node, "layer_size_m");
  settings.cell_size_m = requirePositive(node, "cell_size_m");
  settings.inflation_radius_m = requirePositive(node, "inflation_radius_m");
  settings.simplify_epsilon_m = requirePositive(node, "simplify_epsilon_m");
  settings.min_polygon_area_m2 = requirePositive(node, "min_polygon_area_m2");
  settings.remember_background = node.required<bool>("remember_background");
  settings.gap_fill_azimuth_step_deg = node.required<double>("gap_fill_azimuth_step_deg");
  settings.gap_fill_min_incidence_deg = node.required<double>("gap_fill_min_incidence_deg");
  if (const auto problem = gapFillProblem(settings)) {
    node.fail(problem->key, problem->reason);
  }
  if (settings.vehicle_height_m <= settings.ground_clearance_m) {
    node.fail("vehicle_height_m", "must be above ground_clearance_m");
  }
  if (settings.cell_size_m > settings.layer_size_m) {
    node.fail("cell_size_m", "must not exceed layer_size_m");
  }
  if (settings.layer_size_m / settings.cell_size_m > kMaxLayerCells) {
    node.fail("cell_size_m", "gives more than 20000 cells per side of the layer; use larger cells");
  }
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::perception
