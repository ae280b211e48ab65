#include "sim/importers/namosim_svg_importer.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/geometry/polygon.hpp"
#include "sim/importers/grid_importer.hpp"
#include "sim/importers/namosim_scene.hpp"
#include "sim/importers/svg_document.hpp"
#include "sim/importers/svg_map_image.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_validation.hpp"

namespace ifar::sim {
namespace {

using geometry::Point;
using geometry::Polygon;

/// Robot and goal outlines only give a centre and a size: a coarse flattening (of the drawing's size) is
/// enough, and it is needed before the scale that sets the walls' tolerance is known.
constexpr double kMarkerTolerance = 1e-4;
/// namosim's unit ("all units in your SVG geometry file must be in centimetres").
constexpr double kNamosimMetresPerUnit = 0.01;

class Converter {
 public:
  Converter(const SvgViewBox& box, double metres_per_unit) : box_(box), scale_(metres_per_unit) {}

  Point toWorld(const Point& svg) const
  {
    return Point((svg.x() - box_.min_x) * scale_, (box_.min_y + box_.height - svg.y()) * scale_);
  }

  Polygon toWorld(const Polygon& polygon) const
  {
    Polygon out;
    out.reserve(polygon.size());
    for (const auto& point : polygon) {
      out.push_back(toWorld(point));
    }
    return geometry::signedArea(out) < 0.0 ? geometry::counterClockwise(std::move(out)) : out;
  }

 private:
  SvgViewBox box_;
  double scale_;
};

NamosimImport failure(std::string message)
{
  NamosimImport import;
  import.world = WorldResult::failure(std::move(message));
  return import;
}

/// Drops consecutive points closer than `same_point` and a closing point equal to the first.
Polygon cleanRing(const std::vector<Point>& points, double same_point)
{
  Polygon ring;
  for (const auto& point : points) {
    if (ring.empty() || (point - ring.back()).norm() > same_point) {
      ring.push_back(point);
    }
  }
  while (ring.size() > 1 && (ring.front() - ring.back()).norm() <= same_point) {
    ring.pop_back();
  }
  return ring;
}

/// The element's closed outlines in root units, or the problem (without the element's name).
std::optional<std::string> closedOutlines(const SvgDocument& document, std::size_t index, double tolerance,
                                          double closing, std::vector<Polygon>& rings)
{
  const SvgPathParse outline = document.outline(index, tolerance);
  if (!outline.error.empty()) {
    return outline.error;
  }
  for (const auto& subpath : outline.subpaths) {
    const bool ends_meet =
        subpath.points.size() > 2 && (subpath.points.front() - subpath.points.back()).norm() <= closing;
    if (!subpath.closed && !ends_meet) {
      return std::string("open path (no closing 'z' and the end is not the start)");
    }
    rings.push_back(cleanRing(subpath.points, closing));
  }
  if (rings.empty()) {
    return std::string("path has no points");
  }
  return std::nullopt;
}

std::string baseName(const std::string& source_name)
{
  const auto slash = source_name.find_last_of('/');
  std::string name = source_name.substr(slash == std::string::npos ? 0 : slash + 1);
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".svg") == 0) {
    name.resize(name.size() - 4);
  }
  return name;
}

/// The robot `wanted` names (id, else position), or the problem.
std::optional<std::size_t> pickRobot(const std::vector<NamosimRobot>& robots, const std::string& wanted,
                                     std::string& problem)
{
  if (wanted.empty()) {
    return robots.empty() ? std::nullopt : std::optional<std::size_t>(0);
  }
  for (std::size_t index = 0; index < robots.size(); ++index) {
    if (robots[index].id == wanted) {
      return index;
    }
  }
  const bool digits = std::all_of(wanted.begin(), wanted.end(),
                                  [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
  if (digits && wanted.size() < 9 && std::stoul(wanted) < robots.size()) {
    return std::stoul(wanted);
  }
  std::string names;
  for (const auto& robot : robots) {
    names += (names.empty() ? "" : ", ") + robot.id;
  }
  problem = "no robot '" + wanted +
            "' (by id or index) in the file; its robots: " + (names.empty() ? std::string("none") : names);
  return std::nullopt;
}

std::string goalList(const NamosimRobot& robot)
{
  if (robot.goals.empty()) {
    return "no goals";
  }
  std::string list = std::to_string(robot.goals.size()) + (robot.goals.size() == 1 ? " goal: " : " goals: ");
  for (std::size_t index = 0; index < robot.goals.size(); ++index) {
    list += (index == 0 ? "" : ", ") + robot.goals[index].id;
  }
  return list;
}

/// The blocked (and unknown) cells of a map bitmap as wall rectangles in root units, `space` mapping the
/// image element's units to the root's. Cells under a movable are free: a map made by a robot's lidar holds
/// the movable objects that stood there, and the scenario's movables take their place.
std::vector<Polygon> mapWalls(SvgMapImage map, const SvgTransform& space,
                              const std::vector<Polygon>& movables)
{
  const auto toRoot = [&](double x, double y) { return Point(space * map.cornerAt(x, y)); };
  if (std::abs(space.linear().determinant()) > 0.0 && map.pixel_size.x() > 0.0 && map.pixel_size.y() > 0.0) {
    const SvgTransform to_image = space.inverse();
    for (const Polygon& movable : movables) {
      Polygon in_pixels;
      for (const Point& vertex : movable) {
        const Point local = to_image * vertex;
        in_pixels.push_back((local - map.origin).cwiseQuotient(map.pixel_size));
      }
      const Eigen::AlignedBox2d box = geometry::boundingBox(in_pixels);
      const auto clampedCell = [](double value, int cells) {
        return value < 0.0 ? 0 : (value >= cells - 1 ? cells - 1 : static_cast<int>(value));
      };
      const int x0 = clampedCell(box.min().x(), map.cells.width());
      const int y0 = clampedCell(box.min().y(), map.cells.height());
      const int x1 = clampedCell(box.max().x(), map.cells.width());
      const int y1 = clampedCell(box.max().y(), map.cells.height());
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const Polygon cell = {Point(x, y), Point(x + 1, y), Point(x + 1, y + 1), Point(x, y + 1)};
          if (geometry::polygonsIntersect(cell, in_pixels)) {
            map.cells.set(x, y, grid_map::Cell::Free);
          }
        }
      }
    }
  }
  std::vector<Polygon> walls;
  for (const CellRectangle& cells : blockedRectangles(map.cells, grid_map::UnknownPolicy::AsBlocked)) {
    walls.push_back({toRoot(cells.x0, cells.y0), toRoot(cells.x1, cells.y0), toRoot(cells.x1, cells.y1),
                     toRoot(cells.x0, cells.y1)});
  }
  return walls;
}

/// The grid point nearest `target` (at `spacing` over `area`) that lies outside every obstacle and object
/// with `clearance` to spare, for a start the file does not give; nullopt when there is none.
std::optional<Point> freePointNear(const World& world, const Point& target, const Eigen::AlignedBox2d& area,
                                   double clearance, double spacing)
{
  std::vector<Polygon> outlines;
  outlines.reserve(world.obstacles.size() + world.objects.size());
  for (const auto& obstacle : world.obstacles) {
    outlines.push_back(obstacle.outline);
  }
  for (const auto& object : world.objects) {
    outlines.push_back(placedOutline(object));
  }
  // At most 200 steps a side (a bound for any drawing, and for non-finite sizes from absurd scales).
  const auto steps = [spacing](double length) {
    const double count = length / spacing;
    return count >= 0.0 && count < 200.0 ? static_cast<int>(count) : (count >= 200.0 ? 200 : 0);
  };
  std::vector<Point> candidates;
  for (int column = 0; column <= steps(area.sizes().x()); ++column) {
    for (int row = 0; row <= steps(area.sizes().y()); ++row) {
      candidates.push_back(area.min() + Point(column * spacing, row * spacing));
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(), [&target](const Point& first, const Point& second) {
    return (first - target).squaredNorm() < (second - target).squaredNorm();
  });
  candidates.insert(candidates.begin(), target);
  for (const Point& candidate : candidates) {
    const bool free = std::none_of(outlines.begin(), outlines.end(), [&](const Polygon& outline) {
      return geometry::containsPoint(outline, candidate) ||
             geometry::distanceToBoundary(outline, candidate) < clearance;
    });
    if (free) {
      return candidate;
    }
  }
  return std::nullopt;
}

/// Four walls just outside `area` (world frame), named edge_south, edge_east, edge_north, edge_west.
void addEdgeWalls(const Eigen::AlignedBox2d& area, const NamosimImportSettings& settings, World& world)
{
  const Point& low = area.min();
  const Point& high = area.max();
  const double thickness = settings.edge_wall_thickness_m;
  const auto rectangle = [](double x0, double y0, double x1, double y1) {
    return Polygon{Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)};
  };
  const std::pair<const char*, Polygon> sides[] = {
      {"edge_south", rectangle(low.x() - thickness, low.y() - thickness, high.x() + thickness, low.y())},
      {"edge_east", rectangle(high.x(), low.y(), high.x() + thickness, high.y())},
      {"edge_north", rectangle(low.x() - thickness, high.y(), high.x() + thickness, high.y() + thickness)},
      {"edge_west", rectangle(low.x() - thickness, low.y(), low.x(), high.y())},
  };
  for (const auto& [name, outline] : sides) {
    StaticObstacle obstacle;
    obstacle.name = name;
    obstacle.outline = outline;
    obstacle.height_m = settings.wall_height_m;
    obstacle.reflectivity = settings.wall_reflectivity;
    world.obstacles.push_back(obstacle);
  }
}

}  // namespace

NamosimImport parseNamosimSvg(const std::string& text, const std::string& source_name,
                              const NamosimImportSettings& settings)
{
  auto parsed = SvgDocument::parse(text);
  if (!parsed.document) {
    return failure(source_name + ": " + parsed.error);
  }
  const SvgDocument& document = *parsed.document;
  const SvgViewBox& view_box = document.viewBox();
  const double drawing_size = view_box.largerSide();
  NamosimSceneRead read = readNamosimScene(document, kMarkerTolerance * drawing_size);
  if (!read.error.empty()) {
    return failure(source_name + ": " + read.error);
  }
  const NamosimScene& scene = read.scene;

  NamosimImport import;
  import.warnings = scene.warnings;
  std::string problem;
  const auto vehicle_index = pickRobot(scene.robots, settings.robot, problem);
  if (!problem.empty()) {
    return failure(source_name + ": " + problem);
  }
  const NamosimRobot* vehicle = vehicle_index ? &scene.robots[*vehicle_index] : nullptr;
  const NamosimMarker* body = vehicle && vehicle->body ? &*vehicle->body : nullptr;

  // Scale: given, else from the vehicle robot's size, else another drawn robot's, else namosim's unit.
  double metres_per_unit = 0.0;
  if (settings.metres_per_unit) {
    metres_per_unit = *settings.metres_per_unit;
    if (!(metres_per_unit > 0.0) || !std::isfinite(metres_per_unit)) {
      return failure(source_name + ": scale must be positive, got " + std::to_string(metres_per_unit));
    }
  } else if (body) {
    if (!(body->size > 0.0)) {
      return failure(source_name + ": " + body->label + ": robot has zero size, cannot derive the scale");
    }
    metres_per_unit = settings.vehicle_width_m / body->size;
    import.robot_diameter_units = body->size;
  } else {
    const auto drawn = std::find_if(scene.robots.begin(), scene.robots.end(), [](const NamosimRobot& robot) {
      return robot.body && robot.body->size > 0.0;
    });
    if (drawn != scene.robots.end()) {
      metres_per_unit = settings.vehicle_width_m / drawn->body->size;
      import.warnings.push_back("scale taken from robot '" + drawn->id +
                                "' (the vehicle robot is not drawn)");
    } else {
      metres_per_unit = kNamosimMetresPerUnit;
      import.warnings.push_back(
          std::string(
              "no robot drawn to take the scale from: 1 SVG unit = 1 cm, namosim's unit (--scale sets "
              "metres per unit") +
          (scene.images.empty()
               ? ")"
               : "; where a map bitmap gives the walls a unit is one of its pixels, and --scale "
                 "is the map's resolution)"));
    }
  }
  if (body) {
    import.robot_diameter_units = body->size;
  }
  const Converter converter(view_box, metres_per_unit);
  // The viewBox in the world frame (y flipped: its bottom edge is the world's low y).
  const Eigen::AlignedBox2d view_area(
      converter.toWorld(Point(view_box.min_x, view_box.min_y + view_box.height)),
      converter.toWorld(Point(view_box.min_x + view_box.width, view_box.min_y)));
  const double closing = settings.closing_tolerance * drawing_size;
  const double curve_tolerance = std::max(settings.curve_tolerance_m / metres_per_unit, 0.0);

  World world;
  world.source = source_name;
  world.name = baseName(source_name);
  for (const std::size_t wall : scene.walls) {
    std::vector<Polygon> rings;
    if (const auto bad = closedOutlines(document, wall, curve_tolerance, closing, rings)) {
      return failure(source_name + ": " + document.describe(wall) + ": " + *bad);
    }
    const std::string id = document.element(wall).attribute("id").value_or("");
    for (std::size_t index = 0; index < rings.size(); ++index) {
      StaticObstacle obstacle;
      obstacle.name =
          (id.empty() ? "wall" : id) + (rings.size() > 1 ? "_" + std::to_string(index) : std::string());
      obstacle.outline = converter.toWorld(rings[index]);
      obstacle.height_m = settings.wall_height_m;
      obstacle.reflectivity = settings.wall_reflectivity;
      if (const auto polygon_problem = polygonProblem(obstacle.outline)) {
        return failure(source_name + ": " + document.describe(wall) + ": " + *polygon_problem);
      }
      world.obstacles.push_back(std::move(obstacle));
    }
  }
  std::int64_t next_id = 1;
  std::vector<Polygon> movable_outlines;  // root units, for the map bitmaps below
  for (const std::size_t movable : scene.movables) {
    std::vector<Polygon> rings;
    if (const auto bad = closedOutlines(document, movable, curve_tolerance, closing, rings)) {
      return failure(source_name + ": " + document.describe(movable) + ": " + *bad);
    }
    if (rings.size() != 1) {
      return failure(source_name + ": " + document.describe(movable) +
                     ": a movable needs exactly one closed outline, got " + std::to_string(rings.size()));
    }
    movable_outlines.push_back(rings.front());
    MovableObject object;
    object.id = next_id++;
    const std::string id = document.element(movable).attribute("id").value_or("");
    object.name = id.empty() ? "movable_" + std::to_string(object.id) : id;
    const Polygon outline = converter.toWorld(rings.front());
    if (const auto polygon_problem = polygonProblem(outline)) {
      return failure(source_name + ": " + document.describe(movable) + ": " + *polygon_problem);
    }
    const Point centre = geometry::centroid(outline);
    for (const auto& vertex : outline) {
      object.outline.push_back(vertex - centre);
    }
    object.pose.x = centre.x();
    object.pose.y = centre.y();
    object.mass_kg = settings.object_mass_kg;
    object.ground_friction = settings.object_ground_friction;
    object.height_m = settings.object_height_m;
    object.reflectivity = settings.object_reflectivity;
    world.objects.push_back(std::move(object));
  }
  for (const std::size_t image : scene.images) {
    std::string image_problem;
    const auto map = readSvgMapImage(document.element(image), image_problem);
    if (!map) {
      import.warnings.push_back(document.describe(image) + ": map_layer image not read: " + image_problem);
      continue;
    }
    const std::string id = document.element(image).attribute("id").value_or("map_image");
    std::size_t index = 0;
    for (Polygon& wall : mapWalls(*map, document.userSpace(image), movable_outlines)) {
      StaticObstacle obstacle;
      obstacle.name = id + "_cells_" + std::to_string(index++);
      obstacle.outline = converter.toWorld(wall);
      obstacle.height_m = settings.wall_height_m;
      obstacle.reflectivity = settings.wall_reflectivity;
      world.obstacles.push_back(std::move(obstacle));
    }
  }

  // Every robot in the world frame; the vehicle's start and goals go into the world.
  for (const auto& robot : scene.robots) {
    NamosimRobotSummary summary;
    summary.id = robot.id;
    if (robot.body) {
      const Point start = converter.toWorld(robot.body->centre);
      summary.start = geometry::Pose2{start.x(), start.y(), robot.body->heading.value_or(0.0)};
    }
    for (const auto& goal : robot.goals) {
      summary.goal_names.push_back(goal.id);
      summary.goals.push_back(converter.toWorld(goal.centre));
    }
    import.robots.push_back(std::move(summary));
  }
  if (vehicle) {
    import.vehicle_robot = vehicle->id;
    const NamosimRobotSummary& summary = import.robots[*vehicle_index];
    for (std::size_t index = 0; index < summary.goals.size(); ++index) {
      world.goals.push_back(Goal{summary.goal_names[index], summary.goals[index]});
    }
    for (std::size_t index = 0; index < scene.robots.size(); ++index) {
      if (index != *vehicle_index) {
        import.warnings.push_back("robot '" + scene.robots[index].id + "' (" + goalList(scene.robots[index]) +
                                  ") not simulated: the vehicle is robot '" + vehicle->id + "' (--robot " +
                                  scene.robots[index].id + " picks it)");
      }
    }
  }
  const std::optional<geometry::Pose2> drawn_start =
      vehicle_index ? import.robots[*vehicle_index].start : std::optional<geometry::Pose2>();
  if (drawn_start) {
    world.start = *drawn_start;
  } else if (settings.start) {
    world.start = *settings.start;
  } else {
    const double clearance = 0.5 * settings.vehicle_width_m;
    const Point spot = freePointNear(world, view_area.center(), view_area, clearance,
                                     std::max(clearance, view_area.sizes().maxCoeff() / 200.0))
                           .value_or(view_area.center());
    world.start = geometry::Pose2{spot.x(), spot.y(), 0.0};
  }

  const bool drew_walls = !world.obstacles.empty();
  if (settings.edge_wall_thickness_m > 0.0) {
    addEdgeWalls(view_area, settings, world);
  }

  // A world without walls, vehicle or goals is written, but said to be incomplete.
  if (!drew_walls) {
    import.incomplete = true;
    import.warnings.push_back(
        "no walls: no drawing element has type=\"wall\" and no map_layer bitmap holds any");
  }
  if (!drawn_start && !settings.start) {
    import.incomplete = true;
    import.warnings.push_back(std::string(vehicle ? "robot '" + vehicle->id + "' is not drawn" : "no robot") +
                              ": the start is the free spot nearest the centre of the viewBox, (" +
                              std::to_string(world.start.x) + ", " + std::to_string(world.start.y) +
                              ") m; give one with --start");
  }
  if (world.goals.empty()) {
    import.incomplete = true;
    import.warnings.push_back(vehicle ? "no goals: robot '" + vehicle->id + "' has none"
                                      : std::string("no goals: the file has no robot and no goal"));
  }
  updateBounds(world);
  const auto problems = findWorldProblems(world);
  if (!problems.empty()) {
    return failure(describeProblems(source_name, problems));
  }
  import.world = WorldResult::success(std::move(world));
  import.metres_per_unit = metres_per_unit;
  return import;
}

NamosimImport importNamosimSvg(const std::string& path, const NamosimImportSettings& settings)
{
  std::ifstream in(path);
  if (!in) {
    return failure(path + ": cannot open SVG file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseNamosimSvg(text.str(), path, settings);
}

}  // namespace ifar::sim
