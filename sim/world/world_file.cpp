#include "sim/world/world_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

#include "common/config.hpp"
#include "common/geometry/angle.hpp"
#include "sim/world/world_geometry.hpp"
#include "sim/world/world_validation.hpp"

namespace ifar::sim {
namespace {

double unitScale(const common::ConfigNode& root)
{
  const auto units = root.required<std::string>("units");
  if (units == "m") {
    return 1.0;
  }
  if (units == "cm") {
    return 0.01;
  }
  if (units == "mm") {
    return 0.001;
  }
  root.fail("units", "unknown units '" + units + "' (expected m, cm or mm)");
}

geometry::Polygon readPolygon(const common::ConfigNode& node, double scale)
{
  const auto values = node.required<std::vector<double>>("polygon");
  if (values.size() % 2 != 0) {
    node.fail("polygon",
              "needs x, y pairs, got an odd count of " + std::to_string(values.size()) + " numbers");
  }
  geometry::Polygon polygon;
  for (std::size_t index = 0; index + 1 < values.size(); index += 2) {
    polygon.emplace_back(values[index] * scale, values[index + 1] * scale);
  }
  return polygon;
}

/// A length in the file's units, or `fallback_m` (already metres) when absent.
double readLength(const common::ConfigNode& node, const std::string& key, double scale, double fallback_m)
{
  return node.has(key) ? node.required<double>(key) * scale : fallback_m;
}

geometry::Pose2 readPose(const common::ConfigNode& parent, const std::string& key, double scale)
{
  const auto node = parent.child(key);
  geometry::Pose2 pose;
  pose.x = node.required<double>("x") * scale;
  pose.y = node.required<double>("y") * scale;
  pose.heading = geometry::radiansFromDegrees(node.optional<double>("heading_deg", 0.0));
  return pose;
}

/// Counter-clockwise order; zero-area polygons are left for validation to report.
geometry::Polygon orient(geometry::Polygon polygon)
{
  return geometry::signedArea(polygon) < 0.0 ? geometry::counterClockwise(std::move(polygon)) : polygon;
}

/// Moves the body frame to the outline's centroid, keeping the object where it is in the world.
void centreBodyFrame(MovableObject& object)
{
  if (object.outline.size() < 3 || geometry::area(object.outline) <= geometry::kEpsilon) {
    return;
  }
  const geometry::Point offset = geometry::centroid(object.outline);
  if (offset.norm() <= geometry::kEpsilon) {
    return;
  }
  for (auto& vertex : object.outline) {
    vertex -= offset;
  }
  const geometry::Point origin = object.pose.transform(offset);
  object.pose.x = origin.x();
  object.pose.y = origin.y();
}

World readWorld(const common::ConfigNode& root)
{
  World world;
  world.source = root.sourceName();
  world.name = root.required<std::string>("name");
  const double scale = unitScale(root);
  world.start = readPose(root, "start", scale);

  for (const auto& node : root.sequence("goals")) {
    Goal goal;
    goal.name = node.optional<std::string>("name", "goal_" + std::to_string(world.goals.size()));
    goal.position = geometry::Point(node.required<double>("x") * scale, node.required<double>("y") * scale);
    node.rejectUnknownKeys();
    world.goals.push_back(goal);
  }
  for (const auto& node : root.sequence("obstacles")) {
    StaticObstacle obstacle;
    obstacle.name = node.optional<std::string>("name", "obstacle_" + std::to_string(world.obstacles.size()));
    obstacle.outline = orient(readPolygon(node, scale));
    obstacle.height_m = readLength(node, "height", scale, obstacle.height_m);
    obstacle.reflectivity = node.optional<double>("reflectivity", obstacle.reflectivity);
    node.rejectUnknownKeys();
    world.obstacles.push_back(std::move(obstacle));
  }
  for (const auto& node : root.sequence("objects")) {
    MovableObject object;
    object.id = node.required<std::int64_t>("id");
    object.name = node.optional<std::string>("name", "object_" + std::to_string(object.id));
    object.outline = orient(readPolygon(node, scale));
    object.pose = readPose(node, "pose", scale);
    object.mass_kg = node.required<double>("mass_kg");
    object.ground_friction = node.optional<double>("ground_friction", object.ground_friction);
    object.reflectivity = node.optional<double>("reflectivity", object.reflectivity);
    object.height_m = readLength(node, "height", scale, object.height_m);
    node.rejectUnknownKeys();
    centreBodyFrame(object);
    world.objects.push_back(std::move(object));
  }
  root.rejectUnknownKeys();
  updateBounds(world);
  return world;
}

/// Shortest text that reads back as the same double.
std::string number(double value)
{
  if (value == 0.0) {
    return "0";  // also folds -0
  }
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

void writePolygon(std::ostream& out, const geometry::Polygon& polygon)
{
  out << "    polygon: [";
  for (std::size_t index = 0; index < polygon.size(); ++index) {
    out << (index == 0 ? "" : ",  ") << number(polygon[index].x()) << ", " << number(polygon[index].y());
  }
  out << "]\n";
}

/// Degrees to 12 significant digits: radians -> degrees -> radians is not exact, and this keeps a saved
/// file stable when loaded and saved again (within 1e-13 rad of the original).
std::string degrees(double radians)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), geometry::degreesFromRadians(radians),
                                    std::chars_format::general, 12);
  const std::string text(buffer, result.ptr);
  return text == "-0" ? "0" : text;
}

std::string pose(const geometry::Pose2& value)
{
  return "{x: " + number(value.x) + ", y: " + number(value.y) + ", heading_deg: " + degrees(value.heading) +
         "}";
}

/// YAML double-quoted scalar, so names with ':' or '#' survive.
std::string quoted(const std::string& text)
{
  std::string out = "\"";
  for (const char character : text) {
    if (character == '"' || character == '\\') {
      out += '\\';
    }
    out += character;
  }
  return out + "\"";
}

}  // namespace

WorldResult parseWorld(const std::string& text, const std::string& source_name)
{
  World world;
  try {
    world = readWorld(common::ConfigNode::loadString(text, source_name));
  } catch (const common::ConfigError& error) {
    return WorldResult::failure(error.what());
  }
  const auto problems = findWorldProblems(world);
  if (!problems.empty()) {
    return WorldResult::failure(describeProblems(source_name, problems));
  }
  return WorldResult::success(std::move(world));
}

WorldResult loadWorldFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in) {
    return WorldResult::failure(path + ": cannot open world file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    return WorldResult::failure(path + ": cannot read world file");
  }
  return parseWorld(text.str(), path);
}

std::string formatWorld(const World& world)
{
  std::ostringstream out;
  out << "# ifar world (format: docs/worlds.md). Lengths in metres, headings in degrees, polygons as x, y "
         "pairs.\n";
  out << "name: " << quoted(world.name) << "\n";
  out << "units: m\n";
  out << "start: " << pose(world.start) << "\n";
  out << "goals:" << (world.goals.empty() ? " []" : "") << "\n";
  for (const auto& goal : world.goals) {
    out << "  - {name: " << quoted(goal.name) << ", x: " << number(goal.position.x())
        << ", y: " << number(goal.position.y()) << "}\n";
  }
  out << "obstacles:" << (world.obstacles.empty() ? " []" : "") << "\n";
  for (const auto& obstacle : world.obstacles) {
    out << "  - name: " << quoted(obstacle.name) << "\n";
    out << "    height: " << number(obstacle.height_m) << "\n";
    out << "    reflectivity: " << number(obstacle.reflectivity) << "\n";
    writePolygon(out, obstacle.outline);
  }
  out << "objects:" << (world.objects.empty() ? " []" : "") << "\n";
  for (const auto& object : world.objects) {
    out << "  - id: " << object.id << "\n";
    out << "    name: " << quoted(object.name) << "\n";
    out << "    pose: " << pose(object.pose) << "\n";
    out << "    mass_kg: " << number(object.mass_kg) << "\n";
    out << "    ground_friction: " << number(object.ground_friction) << "\n";
    out << "    reflectivity: " << number(object.reflectivity) << "\n";
    out << "    height: " << number(object.height_m) << "\n";
    writePolygon(out, object.outline);
  }
  return out.str();
}

std::string saveWorldFile(const World& world, const std::string& path)
{
  std::ofstream out(path, std::ios::trunc);
  if (!out) {
    return path + ": cannot open for writing";
  }
  out << formatWorld(world);
  out.close();
  if (!out) {
    return path + ": write failed";
  }
  return {};
}

}  // namespace ifar::sim
