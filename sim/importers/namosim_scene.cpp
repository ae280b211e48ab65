#include "sim/importers/namosim_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "common/geometry/polygon.hpp"
#include "sim/importers/svg_number.hpp"
#include "sim/importers/svg_shapes.hpp"

namespace ifar::sim {
namespace {

using geometry::Point;

constexpr double kPi = 3.14159265358979323846;

bool isNamosimType(const std::string& value)
{
  return value == "wall" || value == "movable" || value == "shape" || value == "orientation" ||
         value == "robot";
}

/// namosim's `type` attribute; a namespaced one (namo:type) counts when its value is one of namosim's, so
/// Inkscape's sodipodi:type="star" does not.
std::string namosimType(const XmlElement& element)
{
  if (const auto plain = element.attribute("type")) {
    return *plain;
  }
  for (const auto& [key, value] : element.attributes) {
    const auto colon = key.rfind(':');
    if (colon != std::string::npos && key.compare(colon + 1, std::string::npos, "type") == 0 &&
        isNamosimType(value)) {
      return value;
    }
  }
  return {};
}

/// N when `text` is `prefix` followed by decimal digits only.
std::optional<long> numberAfter(const std::string& text, const std::string& prefix)
{
  if (text.size() <= prefix.size() || text.compare(0, prefix.size(), prefix) != 0 ||
      text.size() > prefix.size() + 9) {
    return std::nullopt;
  }
  long value = 0;
  for (std::size_t index = prefix.size(); index < text.size(); ++index) {
    if (std::isdigit(static_cast<unsigned char>(text[index])) == 0) {
      return std::nullopt;
    }
    value = value * 10 + (text[index] - '0');
  }
  return value;
}

struct RobotGoalId {
  long robot = 0;
  long goal = 0;
};

/// robot_N_goal_M.
std::optional<RobotGoalId> robotGoalId(const std::string& id)
{
  const auto split = id.find("_goal_");
  if (split == std::string::npos) {
    return std::nullopt;
  }
  const auto robot = numberAfter(id.substr(0, split), "robot_");
  const auto goal = numberAfter(id.substr(split + 1), "goal_");
  if (!robot || !goal) {
    return std::nullopt;
  }
  return RobotGoalId{*robot, *goal};
}

bool looksLikeRobotOrGoal(const std::string& id)
{
  return numberAfter(id, "robot_") || numberAfter(id, "goal_") || robotGoalId(id);
}

class SceneBuilder {
 public:
  SceneBuilder(const SvgDocument& document, double tolerance)
      : document_(document), tolerance_(tolerance), taken_(document.elements().size(), false)
  {
  }

  NamosimSceneRead run()
  {
    const auto config = findConfig();
    if (config) {
      readConfiguredAgents(*config);
    } else if (findLayer("robots_layer") || findLayer("goals_layer")) {
      readLayers();
    } else {
      readByNames();
    }
    if (!read_.error.empty()) {
      return std::move(read_);
    }
    classifyTheRest(config.has_value());
    return std::move(read_);
  }

 private:
  const XmlElement& element(std::size_t index) const { return document_.element(index); }
  std::size_t count() const { return document_.elements().size(); }

  std::optional<std::size_t> findConfig() const
  {
    for (std::size_t index = 0; index < count(); ++index) {
      if (element(index).localName() == "namo_config") {
        return index;
      }
    }
    return std::nullopt;
  }

  std::optional<std::size_t> findLayer(const std::string& id) const
  {
    const auto found = document_.findById(id);
    if (found && document_.isDrawn(*found)) {
      return found;
    }
    return std::nullopt;
  }

  /// Drawing elements inside `ancestor`, in document order (descendants follow their ancestor).
  std::vector<std::size_t> shapesInside(std::size_t ancestor) const
  {
    std::vector<std::size_t> inside;
    for (std::size_t index = ancestor + 1; index < count() && document_.isInside(index, ancestor); ++index) {
      if (document_.isDrawn(index) && isSvgShapeElement(element(index).localName())) {
        inside.push_back(index);
      }
    }
    return inside;
  }

  void fail(std::size_t index, const std::string& problem)
  {
    if (read_.error.empty()) {
      read_.error = document_.describe(index) + ": " + problem;
    }
  }

  /// Every point of the element's outline in root units; false (with the error set) when it cannot be read.
  bool outlinePoints(std::size_t index, std::vector<Point>& points)
  {
    const SvgPathParse outline = document_.outline(index, tolerance_);
    if (!outline.error.empty()) {
      fail(index, outline.error);
      return false;
    }
    for (const auto& subpath : outline.subpaths) {
      points.insert(points.end(), subpath.points.begin(), subpath.points.end());
    }
    return true;
  }

  /// The `angle` attribute in radians; false (with the error set) when it is not a number.
  bool angleAttribute(std::size_t index, std::optional<double>& heading)
  {
    const auto text = element(index).attribute("angle");
    if (!text) {
      return true;
    }
    const auto numbers = parseSvgNumberList(*text);
    if (!numbers || numbers->size() != 1 || !std::isfinite(numbers->front())) {
      fail(index, "attribute 'angle' is not a number of degrees: '" + text->substr(0, 40) + "'");
      return false;
    }
    heading = numbers->front() * kPi / 180.0;
    return true;
  }

  /// A robot's body or a goal from the element with that id: a drawing element, or a group holding the
  /// outline (type="shape", else every drawing element but the heading mark) and a heading mark.
  std::optional<NamosimMarker> readMarker(std::size_t index, const std::string& what)
  {
    NamosimMarker marker;
    marker.id = element(index).attribute("id").value_or("");
    marker.label = document_.describe(index);
    std::vector<Point> points;
    std::optional<double> heading;
    if (!angleAttribute(index, heading)) {
      return std::nullopt;
    }
    if (isSvgShapeElement(element(index).localName())) {
      if (!outlinePoints(index, points)) {
        return std::nullopt;
      }
      taken_[index] = true;
    } else {
      const std::vector<std::size_t> inside = shapesInside(index);
      std::vector<std::size_t> outline;
      std::optional<std::size_t> orientation;
      for (const std::size_t part : inside) {
        const std::string type = namosimType(element(part));
        if (type == "shape") {
          outline.push_back(part);
        } else if (type == "orientation" && !orientation) {
          orientation = part;
        }
      }
      if (outline.empty()) {
        std::copy_if(inside.begin(), inside.end(), std::back_inserter(outline),
                     [&orientation](std::size_t part) { return part != orientation; });
      }
      if (outline.empty()) {
        read_.scene.warnings.push_back(marker.label + ": " + what + " '" + marker.id +
                                       "' is neither a drawing element nor a group holding one: not used");
        return std::nullopt;
      }
      for (const std::size_t part : outline) {
        if (!outlinePoints(part, points) || !angleAttribute(part, heading)) {
          return std::nullopt;
        }
      }
      if (orientation) {
        std::vector<Point> mark;
        if (!outlinePoints(*orientation, mark)) {
          return std::nullopt;
        }
        if (mark.size() >= 2 && mark[1] != mark[0]) {
          heading =
              std::atan2(-(mark[1].y() - mark[0].y()), mark[1].x() - mark[0].x());  // y down in the file
        }
      }
      for (std::size_t part = index; part < count() && (part == index || document_.isInside(part, index));
           ++part) {
        taken_[part] = true;
      }
    }
    if (points.empty()) {
      fail(index, what + " outline has no points");
      return std::nullopt;
    }
    const Eigen::AlignedBox2d box = geometry::boundingBox(points);
    marker.size = box.sizes().maxCoeff();
    const double area = std::abs(geometry::signedArea(points));
    marker.centre = area > 1e-9 * marker.size * marker.size ? geometry::centroid(points) : box.center();
    marker.heading = heading;
    return marker;
  }

  NamosimRobot& robotNamed(const std::string& id)
  {
    for (auto& robot : read_.scene.robots) {
      if (robot.id == id) {
        return robot;
      }
    }
    read_.scene.robots.push_back(NamosimRobot{id, std::nullopt, {}});
    return read_.scene.robots.back();
  }

  void readConfiguredAgents(std::size_t config)
  {
    for (std::size_t agent = config + 1; agent < count() && document_.isInside(agent, config); ++agent) {
      if (element(agent).localName() != "agent") {
        continue;
      }
      const auto id = element(agent).attribute("agent_id");
      if (!id || id->empty()) {
        read_.scene.warnings.push_back("<agent> of <namo_config> (line " +
                                       std::to_string(element(agent).line) + ") has no agent_id: not used");
        continue;
      }
      NamosimRobot robot{*id, std::nullopt, {}};
      if (const auto body = document_.findById(*id)) {
        robot.body = readMarker(*body, "robot");
      } else {
        read_.scene.warnings.push_back(
            "agent '" + *id +
            "' of <namo_config> has no element with that id: the file does not say where it "
            "starts");
      }
      for (std::size_t goal = agent + 1; goal < count() && document_.isInside(goal, agent); ++goal) {
        if (element(goal).localName() != "goal" || element(goal).parent != static_cast<int>(agent)) {
          continue;
        }
        const std::string goal_id = element(goal).attribute("goal_id").value_or("");
        const auto found = goal_id.empty() ? std::nullopt : document_.findById(goal_id);
        if (!found) {
          read_.scene.warnings.push_back("goal '" + goal_id + "' of agent '" + *id +
                                         "' in <namo_config> has no element with that id: not used");
          continue;
        }
        if (auto marker = readMarker(*found, "goal")) {
          robot.goals.push_back(std::move(*marker));
        }
      }
      if (!read_.error.empty()) {
        return;
      }
      read_.scene.robots.push_back(std::move(robot));
    }
  }

  void readLayers()
  {
    if (const auto layer = findLayer("robots_layer")) {
      for (const std::size_t index : shapesInside(*layer)) {
        const std::string type = namosimType(element(index));
        if (type == "wall" || type == "movable") {
          continue;
        }
        const std::string id =
            element(index).attribute("agent_id").value_or(element(index).attribute("id").value_or(""));
        NamosimRobot& robot =
            robotNamed(id.empty() ? "robot_" + std::to_string(read_.scene.robots.size()) : id);
        if (robot.body) {
          read_.scene.warnings.push_back(document_.describe(index) + ": a second outline of robot '" +
                                         robot.id + "' in robots_layer: not used");
          continue;
        }
        robot.body = readMarker(index, "robot");
        if (!read_.error.empty()) {
          return;
        }
      }
    }
    if (const auto layer = findLayer("goals_layer")) {
      for (const std::size_t index : shapesInside(*layer)) {
        auto marker = readMarker(index, "goal");
        if (!read_.error.empty()) {
          return;
        }
        if (!marker) {
          continue;
        }
        const auto agent = element(index).attribute("agent_id");
        const std::string owner =
            agent && !agent->empty()
                ? *agent
                : (read_.scene.robots.empty() ? "robot_0" : read_.scene.robots.front().id);
        robotNamed(owner).goals.push_back(std::move(*marker));
      }
    }
  }

  void readByNames()
  {
    struct Candidate {
      std::size_t index;
      long robot;
      long goal;
    };
    std::vector<Candidate> robots;
    std::vector<Candidate> goals;
    for (std::size_t index = 0; index < count(); ++index) {
      if (!document_.isDrawn(index)) {
        continue;
      }
      const std::string id = element(index).attribute("id").value_or("");
      if (const auto robot = numberAfter(id, "robot_")) {
        robots.push_back({index, *robot, 0});
      } else if (namosimType(element(index)) == "robot") {
        robots.push_back({index, std::numeric_limits<long>::max(), 0});
      } else if (const auto pair = robotGoalId(id)) {
        goals.push_back({index, pair->robot, pair->goal});
      } else if (const auto goal = numberAfter(id, "goal_")) {
        goals.push_back({index, -1, *goal});  // -1: the first robot's
      }
    }
    const auto by_number = [](const Candidate& first, const Candidate& second) {
      return std::make_pair(first.robot, first.goal) < std::make_pair(second.robot, second.goal);
    };
    std::stable_sort(robots.begin(), robots.end(), by_number);
    std::stable_sort(goals.begin(), goals.end(), [](const Candidate& first, const Candidate& second) {
      return first.goal < second.goal;
    });
    for (const Candidate& candidate : robots) {
      if (taken_[candidate.index]) {
        continue;
      }
      const std::string id = element(candidate.index).attribute("id").value_or("");
      NamosimRobot& robot =
          robotNamed(id.empty() ? "robot_" + std::to_string(read_.scene.robots.size()) : id);
      robot.body = readMarker(candidate.index, "robot");
      if (!read_.error.empty()) {
        return;
      }
    }
    for (const Candidate& candidate : goals) {
      if (taken_[candidate.index]) {
        continue;  // part of a group already read
      }
      auto marker = readMarker(candidate.index, "goal");
      if (!read_.error.empty()) {
        return;
      }
      if (!marker) {
        continue;
      }
      const std::string owner = candidate.robot >= 0         ? "robot_" + std::to_string(candidate.robot)
                                : read_.scene.robots.empty() ? "robot_0"
                                                             : read_.scene.robots.front().id;
      robotNamed(owner).goals.push_back(std::move(*marker));
    }
  }

  void classifyTheRest(bool configured)
  {
    const auto movables_layer = findLayer("movables_layer");
    const auto map_layer = findLayer("map_layer");
    for (std::size_t index = 0; index < count(); ++index) {
      if (!document_.isDrawn(index) || taken_[index]) {
        continue;
      }
      const XmlElement& item = element(index);
      if (item.localName() == "image" && map_layer && document_.isInside(index, *map_layer)) {
        read_.scene.images.push_back(index);
        continue;
      }
      const std::string type = namosimType(item);
      const bool shape = isSvgShapeElement(item.localName());
      if (shape && type == "wall") {
        read_.scene.walls.push_back(index);
      } else if (shape && (type == "movable" ||
                           (type.empty() && movables_layer && document_.isInside(index, *movables_layer)))) {
        read_.scene.movables.push_back(index);
      } else if (looksLikeRobotOrGoal(item.attribute("id").value_or("")) || type == "shape" ||
                 type == "robot") {
        read_.scene.warnings.push_back(
            document_.describe(index) + " looks like a robot or goal, but " +
            (configured ? "no agent of <namo_config> lists it" : "nothing makes it one") + ": not used");
      }
    }
  }

  const SvgDocument& document_;
  const double tolerance_;
  std::vector<bool> taken_;  // elements read as a robot's body or a goal (or part of one)
  NamosimSceneRead read_;
};

}  // namespace

NamosimSceneRead readNamosimScene(const SvgDocument& document, double tolerance)
{
  return SceneBuilder(document, tolerance).run();
}

}  // namespace ifar::sim
