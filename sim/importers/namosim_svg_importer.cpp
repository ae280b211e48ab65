#include "sim/importers/namosim_svg_importer.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/geometry/polygon.hpp"
#include "sim/importers/svg_path.hpp"
#include "sim/importers/xml_elements.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_validation.hpp"

namespace ifar::sim {
namespace {

using geometry::Point;
using geometry::Polygon;

/// SVG units closer than this are one point ("v 0" in the data, a repeated closing vertex).
constexpr double kSamePointUnits = 1e-7;

struct ViewBox {
  double min_x = 0.0;
  double min_y = 0.0;
  double width = 0.0;
  double height = 0.0;
};

struct Shape {
  std::string label;  // "element 'wall_1' (line 12)"
  std::string id;
  std::vector<Polygon> polygons;  // SVG units, y down
};

std::string describe(const XmlElement& element)
{
  const auto id = element.attribute("id");
  return "element <" + element.name + ">" + (id ? " '" + *id + "'" : std::string()) + " (line " +
         std::to_string(element.line) + ")";
}

std::optional<ViewBox> parseViewBox(const std::string& text)
{
  ViewBox box;
  // Numbers separated by spaces and/or commas.
  std::string cleaned = text;
  for (auto& character : cleaned) {
    if (character == ',') {
      character = ' ';
    }
  }
  std::istringstream clean_in(cleaned);
  if (!(clean_in >> box.min_x >> box.min_y >> box.width >> box.height) || box.width <= 0.0 ||
      box.height <= 0.0) {
    return std::nullopt;
  }
  return box;
}

/// Drops repeated consecutive points and a closing point equal to the first.
Polygon cleanRing(const std::vector<Point>& points)
{
  Polygon ring;
  for (const auto& point : points) {
    if (ring.empty() || (point - ring.back()).norm() > kSamePointUnits) {
      ring.push_back(point);
    }
  }
  while (ring.size() > 1 && (ring.front() - ring.back()).norm() <= kSamePointUnits) {
    ring.pop_back();
  }
  return ring;
}

/// The element's outline(s) in SVG units; an error message when it cannot be read.
std::optional<std::string> readShape(const XmlElement& element, const NamosimImportSettings& settings,
                                     bool must_be_closed, Shape& shape)
{
  shape.label = describe(element);
  shape.id = element.attribute("id").value_or("");
  if (element.attribute("transform")) {
    return shape.label + ": transform attributes are not supported (apply them to the path first)";
  }
  const std::string local = element.localName();
  if (local == "rect") {
    double values[4] = {0.0, 0.0, 0.0, 0.0};
    const char* keys[4] = {"x", "y", "width", "height"};
    for (int index = 0; index < 4; ++index) {
      const auto text = element.attribute(keys[index]);
      std::istringstream in(text.value_or("0"));
      if (!(in >> values[index])) {
        return shape.label + ": attribute '" + keys[index] + "' is not a number";
      }
    }
    shape.polygons.push_back({Point(values[0], values[1]), Point(values[0] + values[2], values[1]),
                              Point(values[0] + values[2], values[1] + values[3]),
                              Point(values[0], values[1] + values[3])});
    return std::nullopt;
  }
  if (local != "path") {
    return shape.label + ": unsupported element (expected <path> or <rect>)";
  }
  const auto data = element.attribute("d");
  if (!data) {
    return shape.label + ": path has no 'd' attribute";
  }
  const auto parsed = parseSvgPath(*data, settings.curve_segments);
  if (!parsed.error.empty()) {
    return shape.label + ": path data " + parsed.error;
  }
  for (const auto& subpath : parsed.subpaths) {
    const bool ends_at_start = subpath.points.size() > 2 &&
                               (subpath.points.front() - subpath.points.back()).norm() <= kSamePointUnits;
    if (must_be_closed && !subpath.closed && !ends_at_start) {
      return shape.label + ": open path (no closing 'z' and the end is not the start)";
    }
    shape.polygons.push_back(cleanRing(subpath.points));
  }
  if (shape.polygons.empty()) {
    return shape.label + ": path has no points";
  }
  return std::nullopt;
}

struct Extent {
  Point low;
  Point high;
  Point centre() const { return 0.5 * (low + high); }
  double diameter() const { return std::max(high.x() - low.x(), high.y() - low.y()); }
};

Extent extentOf(const Shape& shape)
{
  Extent extent{shape.polygons.front().front(), shape.polygons.front().front()};
  for (const auto& polygon : shape.polygons) {
    for (const auto& point : polygon) {
      extent.low = extent.low.cwiseMin(point);
      extent.high = extent.high.cwiseMax(point);
    }
  }
  return extent;
}

class Converter {
 public:
  Converter(const ViewBox& box, double metres_per_unit) : box_(box), scale_(metres_per_unit) {}

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
  ViewBox box_;
  double scale_;
};

NamosimImport failure(std::string message)
{
  return NamosimImport{WorldResult::failure(std::move(message)), 0.0, 0.0};
}

}  // namespace

NamosimImport parseNamosimSvg(const std::string& text, const std::string& source_name,
                              const NamosimImportSettings& settings)
{
  const auto scan = scanXmlElements(text);
  if (!scan.error.empty()) {
    return failure(source_name + ": malformed XML at " + scan.error);
  }
  std::optional<ViewBox> view_box;
  std::vector<Shape> walls;
  std::vector<Shape> movables;
  std::vector<Shape> goals;
  std::optional<Shape> robot;
  for (const auto& element : scan.elements) {
    const std::string local = element.localName();
    if (local == "svg" && !view_box) {
      const auto attribute = element.attribute("viewBox");
      if (!attribute) {
        return failure(source_name + ": " + describe(element) + ": no viewBox attribute (needed to flip y)");
      }
      view_box = parseViewBox(*attribute);
      if (!view_box) {
        return failure(source_name + ": " + describe(element) + ": viewBox '" + *attribute +
                       "' is not four numbers with positive width and height");
      }
      continue;
    }
    if (local != "path" && local != "rect") {
      continue;  // metadata, namo_config, guides
    }
    const auto type = element.attribute("type").value_or("");
    const auto id = element.attribute("id").value_or("");
    const bool is_goal = id.rfind("goal_", 0) == 0;
    const bool is_robot = id == "robot_0";
    if (type != "wall" && type != "movable" && !is_goal && !is_robot) {
      continue;
    }
    Shape shape;
    if (const auto problem = readShape(element, settings, type == "wall" || type == "movable", shape)) {
      return failure(source_name + ": " + *problem);
    }
    if (type == "wall") {
      walls.push_back(std::move(shape));
    } else if (type == "movable") {
      if (shape.polygons.size() != 1) {
        return failure(source_name + ": " + shape.label +
                       ": a movable needs exactly one closed outline, got " +
                       std::to_string(shape.polygons.size()));
      }
      movables.push_back(std::move(shape));
    } else if (is_robot) {
      robot = std::move(shape);
    } else {
      goals.push_back(std::move(shape));
    }
  }
  if (!view_box) {
    return failure(source_name + ": no <svg> root element with a viewBox");
  }
  if (!robot) {
    return failure(source_name + ": no path with id 'robot_0' (the robot gives the start and the scale)");
  }

  const Extent robot_extent = extentOf(*robot);
  const double robot_diameter = robot_extent.diameter();
  double metres_per_unit = 0.0;
  if (settings.metres_per_unit) {
    metres_per_unit = *settings.metres_per_unit;
    if (!(metres_per_unit > 0.0) || !std::isfinite(metres_per_unit)) {
      return failure(source_name + ": scale must be positive, got " + std::to_string(metres_per_unit));
    }
  } else {
    if (!(robot_diameter > 0.0)) {
      return failure(source_name + ": " + robot->label + ": robot has zero size, cannot derive the scale");
    }
    metres_per_unit = settings.vehicle_width_m / robot_diameter;
  }
  const Converter converter(*view_box, metres_per_unit);

  World world;
  world.source = source_name;
  const auto slash = source_name.find_last_of('/');
  world.name = source_name.substr(slash == std::string::npos ? 0 : slash + 1);
  if (world.name.size() > 4 && world.name.compare(world.name.size() - 4, 4, ".svg") == 0) {
    world.name.resize(world.name.size() - 4);
  }
  world.start.x = converter.toWorld(robot_extent.centre()).x();
  world.start.y = converter.toWorld(robot_extent.centre()).y();
  for (const auto& wall : walls) {
    for (std::size_t index = 0; index < wall.polygons.size(); ++index) {
      StaticObstacle obstacle;
      obstacle.name = (wall.id.empty() ? "wall" : wall.id) +
                      (wall.polygons.size() > 1 ? "_" + std::to_string(index) : std::string());
      obstacle.outline = converter.toWorld(wall.polygons[index]);
      obstacle.height_m = settings.wall_height_m;
      obstacle.reflectivity = settings.wall_reflectivity;
      if (const auto problem = polygonProblem(obstacle.outline)) {
        return failure(source_name + ": " + wall.label + ": " + *problem);
      }
      world.obstacles.push_back(std::move(obstacle));
    }
  }
  std::int64_t next_id = 1;
  for (const auto& movable : movables) {
    MovableObject object;
    object.id = next_id++;
    object.name = movable.id.empty() ? "movable_" + std::to_string(object.id) : movable.id;
    const Polygon outline = converter.toWorld(movable.polygons.front());
    if (const auto problem = polygonProblem(outline)) {
      return failure(source_name + ": " + movable.label + ": " + *problem);
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
  for (const auto& shape : goals) {
    world.goals.push_back(Goal{shape.id, converter.toWorld(extentOf(shape).centre())});
  }
  updateBounds(world);
  const auto problems = findWorldProblems(world);
  if (!problems.empty()) {
    return failure(describeProblems(source_name, problems));
  }
  return NamosimImport{WorldResult::success(std::move(world)), metres_per_unit, robot_diameter};
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
