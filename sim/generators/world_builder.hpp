#pragma once
// Helpers the generators share to lay out walls and boxes and to pick pushable or too-heavy objects.

#include <string>

#include "sim/generators/seeded_random.hpp"
#include "sim/world/world.hpp"

namespace ifar::sim {

/// Axis-aligned rectangle in world metres.
struct Box2 {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;

  /// True when the rectangles grown by `margin` overlap (touching does not count).
  bool overlaps(const Box2& other, double margin = 0.0) const
  {
    return x0 - margin < other.x1 && other.x0 < x1 + margin && y0 - margin < other.y1 &&
           other.y0 < y1 + margin;
  }
  bool contains(const geometry::Point& point, double margin = 0.0) const
  {
    return point.x() > x0 - margin && point.x() < x1 + margin && point.y() > y0 - margin &&
           point.y() < y1 + margin;
  }
};

/// Light objects slide with well under the vehicle's 549 N push; heavy ones need several times more.
enum class ObjectWeight { Light, Heavy };

class WorldBuilder {
 public:
  WorldBuilder(std::string name, std::string source);

  /// A static rectangle (wall, pillar, rock); returns its outline's box.
  Box2 addRectangle(const std::string& prefix, const Box2& box, double height_m = 2.0);

  /// A movable box of size_x x size_y (body frame) centred at `centre`. Mass and friction are drawn from
  /// the weight class: light 15..40 kg at friction 0.4..0.6 (at most 236 N to slide), heavy 250..400 kg
  /// at friction 0.6..0.8 (at least 1472 N).
  void addObject(const geometry::Point& centre, double size_x, double size_y, double heading,
                 ObjectWeight weight, SeededRandom& random);

  void setStart(const geometry::Pose2& start) { world_.start = start; }
  void addGoal(const geometry::Point& position);

  /// Boxes placed so far (static and movable, movable ones by their bounding box), for clearance checks.
  const std::vector<Box2>& occupied() const { return occupied_; }

  /// The finished world with bounds computed.
  World build() const;

 private:
  World world_;
  std::vector<Box2> occupied_;
  int next_obstacle_ = 0;
};

}  // namespace ifar::sim
