#pragma once
// The vehicle's dimensions and limits, from config/vehicle.yaml. One struct shared by simulator,
// planner and executive so they agree on what the vehicle is.

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "common/vehicle_model.hpp"

namespace ifar::common {

/// Which lidar returns are obstacles: facts of the sensor and of the vehicle it is mounted on. The
/// planner's perception and the executive's obstacle points both filter with these (vehicle.yaml
/// `lidar:`), so the two agree on what an obstacle is.
struct LidarFilterSettings {
  double ground_clearance_m = 0.15;  ///< returns lower than this above the ground are the ground
  double max_height_m = 1.2;         ///< returns higher than this above the ground pass over the vehicle
  double min_range_m = 0.4;          ///< closer returns are the vehicle itself (and no-return zeros)
  /// Calibrated reflectivity at or above this marks a retro-reflective tag: a movable object (256: none).
  int movable_reflectivity_threshold = 101;
};

struct VehicleSettings {
  double length_m = 0.9;
  double width_m = 0.7;
  double wheel_track_m = 0.6;
  double wheel_radius_m = 0.15;
  double mass_kg = 80.0;
  double traction_coefficient = 0.7;
  double max_linear_velocity = 1.0;
  double max_angular_velocity = 1.2;
  double max_linear_acceleration = 1.0;
  double max_angular_acceleration = 2.0;
  double bumper_width_m = 0.7;
  double bumper_friction = 0.5;
  double lidar_height_m = 0.8;
  double lidar_x_m = 0.2;
  double force_sensor_range_n = 800.0;
  LidarFilterSettings lidar;

  /// The largest force the wheels can push with before slipping: traction x mass x g.
  double maxPushForce() const { return traction_coefficient * mass_kg * kGravity; }
};

/// vehicle.yaml's keys: every one required.
const ParameterTable<VehicleSettings>& vehicleParameters();

/// Reads every key of vehicle.yaml (all required, all in range) and rejects unknown ones.
VehicleSettings loadVehicleSettings(const ConfigNode& node);

}  // namespace ifar::common
