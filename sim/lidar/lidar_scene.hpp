#pragma once
// What the simulated lidar sees: the world's polygons extruded from the ground to their height, and the
// ground plane. Static walls live in a uniform grid (cells list the wall segments that cross them) that a
// ray walks cell by cell, so a ray costs the cells it crosses, not the number of walls; the few movable
// objects are tested directly behind a bounding-circle check.

#include <cstdint>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim::lidar {

/// An extruded polygon in the world frame.
struct Prism {
  geometry::Polygon outline;  // either orientation
  double height_m = 1.0;
  double reflectivity = 0.2;  // 0..1
};

struct RayHit {
  enum class Surface : std::uint8_t { None, Wall, Top, Ground };
  Surface surface = Surface::None;
  double horizontal_distance = 0.0;  // metres along the ground from the ray's origin
  double reflectivity = 0.0;         // 0..1
  /// Wall hits: |cos| of the angle between the ray's horizontal direction and the face's normal (1 head
  /// on, 0 grazing); tops and the ground are horizontal, so their incidence is the ray's elevation.
  double wall_facing = 1.0;
};

/// A lidar ray: origin at `height` above the ground, horizontal unit direction (cos, sin) and slope
/// tan(elevation); it is followed up to `max_horizontal` metres of ground distance.
struct Ray {
  double origin_x = 0.0;
  double origin_y = 0.0;
  double height = 0.0;
  double direction_x = 1.0;
  double direction_y = 0.0;
  double slope = 0.0;
  double max_horizontal = 100.0;
};

struct LidarSceneSettings {
  double cell_size_m = 2.0;  // grid cell edge
  double ground_reflectivity = 0.08;
};

class LidarScene {
 public:
  LidarScene(const std::vector<Prism>& static_prisms, const LidarSceneSettings& settings);
  /// The world's static obstacles.
  static LidarScene fromWorld(const World& world, const LidarSceneSettings& settings);

  /// Replaces the movable prisms (world frame), e.g. once per physics step.
  void setMovables(std::vector<Prism> movables);

  /// The nearest surface along the ray: a wall face whose height range the ray crosses, the top face of
  /// a prism the ray descends onto, or the ground; Surface::None when nothing is within range.
  RayHit cast(const Ray& ray) const;

  std::size_t staticSegmentCount() const { return segments_.size(); }
  double tallestHeight() const { return tallest_height_; }

 private:
  struct Segment {
    double start_x, start_y, delta_x, delta_y;
    double height;
    double reflectivity;
    double inverse_length;  // 1 / |delta|: a hit's facing without a square root per ray
    std::int32_t prism;
  };
  struct Crossing {
    double distance;
    const Segment* segment;
    bool entering;
  };
  struct MovableEntry {
    double centre_x, centre_y, radius;
    std::size_t first_segment, end_segment;
  };
  class CrossingWalk;

  static void appendSegments(const Prism& prism, std::int32_t index, std::vector<Segment>& segments);
  static bool intersect(const Ray& ray, const Segment& segment, double& distance, bool& entering);
  RayHit castStatic(const Ray& ray, double limit) const;
  RayHit castMovables(const Ray& ray, double limit) const;

  LidarSceneSettings settings_;
  std::vector<Segment> segments_;
  double tallest_height_ = 0.0;
  double grid_min_x_ = 0.0;
  double grid_min_y_ = 0.0;
  int columns_ = 0;
  int rows_ = 0;
  std::vector<std::uint32_t> cell_start_;  // CSR: segments of cell c are cell_items_[cell_start_[c] .. [c+1])
  std::vector<std::uint32_t> cell_items_;
  std::vector<Segment> movable_segments_;
  std::vector<MovableEntry> movables_;
  double movable_tallest_ = 0.0;
};

}  // namespace ifar::sim::lidar
