#include "common/vehicle.hpp"

namespace ifar::common {

const ParameterTable<VehicleSettings>& vehicleParameters()
{
  using S = VehicleSettings;
  using Range = ParameterRange;
  static const auto table =
      ParameterTable<S>(Presence::required)
          .add("length_m", &S::length_m, "m", Range::positive(), "bumper face to rear")
          .add("width_m", &S::width_m, "m", Range::positive(),
               "outer width; the planner inflates obstacles by half of it")
          .add("wheel_track_m", &S::wheel_track_m, "m", Range::positive(),
               "distance between the left and right wheel contact lines")
          .add("wheel_radius_m", &S::wheel_radius_m, "m", Range::positive(), "drive wheel radius")
          .add("mass_kg", &S::mass_kg, "kg", Range::positive(),
               "vehicle mass: with traction, the most it can push")
          .add("traction_coefficient", &S::traction_coefficient, "", Range::positive(),
               "tyre-ground friction: the most the vehicle can push is this x mass x g")
          .add("max_linear_velocity", &S::max_linear_velocity, "m/s", Range::positive(), "top forward speed")
          .add("max_angular_velocity", &S::max_angular_velocity, "rad/s", Range::positive(), "top turn rate")
          .add("max_linear_acceleration", &S::max_linear_acceleration, "m/s^2", Range::positive(),
               "largest forward acceleration")
          .add("max_angular_acceleration", &S::max_angular_acceleration, "rad/s^2", Range::positive(),
               "largest angular acceleration")
          .add("bumper_width_m", &S::bumper_width_m, "m", Range::positive(), "flat bumper across the front")
          .add("bumper_friction", &S::bumper_friction, "", Range::positive(),
               "bumper-object Coulomb coefficient (the pusher friction in stable pushing)")
          .add("lidar_height_m", &S::lidar_height_m, "m", Range::positive(),
               "VLP-16 optical centre above ground")
          .add("lidar_x_m", &S::lidar_x_m, "m", Range::any(),
               "VLP-16 ahead of the vehicle's reference point (negative: behind it)")
          .add("force_sensor_range_n", &S::force_sensor_range_n, "N", Range::positive(),
               "the bumper force sensor saturates (and flags overload) above this")
          .add(
              "lidar.ground_clearance_m", [](auto& s) -> auto& { return s.lidar.ground_clearance_m; }, "m",
              Range::positive(), "returns lower than this above the ground are the ground (flat ground)")
          .add(
              "lidar.max_height_m", [](auto& s) -> auto& { return s.lidar.max_height_m; }, "m",
              Range::positive(),
              "returns higher than this above the ground pass over the vehicle (its height with a margin)")
          .add(
              "lidar.min_range_m", [](auto& s) -> auto& { return s.lidar.min_range_m; }, "m",
              Range::positive(), "closer returns are the vehicle itself or the sensor's no-return zeros")
          .add(
              "lidar.movable_reflectivity_threshold",
              [](auto& s) -> auto& { return s.lidar.movable_reflectivity_threshold; }, "",
              Range::between(1, 256),
              "calibrated reflectivity at or above this is a retro-reflective tag on a movable object (256: "
              "none)");
  return table;
}

VehicleSettings loadVehicleSettings(const ConfigNode& node)
{
  const VehicleSettings settings = vehicleParameters().load(node);
  if (settings.lidar.max_height_m <= settings.lidar.ground_clearance_m) {
    node.fail("lidar.max_height_m", "must be above lidar.ground_clearance_m");
  }
  return settings;
}

}  // namespace ifar::common
