#pragma once
// What a namosim scenario SVG says, by namosim's own conventions (Chroma-CITI/namosim: World.load_from_svg
// and the layered SVG of its ROS-map scenarios, World.load_agents / load_movables / load_goals):
//
// - Walls are drawing elements with type="wall", movables those with type="movable" (a namespaced type
//   such as namo:type="movable" counts too), and in the layered form every drawing element of the layer
//   with id "movables_layer".
// - Robots are the agents of <namo_config> (<agent agent_id="...">) in their order; the element with that
//   id is the robot's outline, or a group holding its outline (type="shape") and a heading mark
//   (type="orientation": from its first point to its second). An `angle` attribute gives the heading in
//   degrees, counter-clockwise with y up. Without a namo_config: the drawing elements of the layer
//   "robots_layer" (named by their agent_id attribute, else their id); without that layer, elements with
//   type="robot" or an id robot_N.
// - Goals are each agent's <goal goal_id="..."> in order, the element being an outline or a group as for
//   robots. Without a namo_config: the drawing elements of "goals_layer", each the goal of the robot its
//   agent_id names (the first robot's without one), in document order; without that layer, ids
//   robot_N_goal_M (robot N's, in the order of M) and goal_M (the first robot's, in the order of M).
// - A robot or goal stands at the area centroid of its outline (as namosim places it; the centre of its
//   bounding box when the outline encloses no area); its size is the larger side of that box.
//
// A robot the file names (an agent, a goal's agent_id) without drawing it has no body: namosim takes such a
// robot's start from the scenario's YAML. Nothing listed is dropped silently: every agent or goal without
// its element, and every element that looks like a robot or goal (id robot_N, goal_N, robot_N_goal_M) but
// is not one, is a warning.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sim/importers/svg_document.hpp"

namespace ifar::sim {

/// A robot's body or a goal, in root user units (y down).
struct NamosimMarker {
  std::string id;
  std::string label;  // "element <path> 'goal_0' (line 12)"
  geometry::Point centre;
  double size = 0.0;              // larger side of the bounding box
  std::optional<double> heading;  // radians, counter-clockwise with y up (the world's sense)
};

struct NamosimRobot {
  std::string id;
  std::optional<NamosimMarker> body;  // empty when the file names the robot without drawing it
  std::vector<NamosimMarker> goals;   // in the order the robot drives them
};

struct NamosimScene {
  std::vector<std::size_t> walls;     // element indices, document order
  std::vector<std::size_t> movables;  // element indices, document order
  std::vector<std::size_t> images;    // <image> elements of the layer "map_layer"
  std::vector<NamosimRobot> robots;
  std::vector<std::string> warnings;  // what the file lists or suggests and the scene does not use
};

struct NamosimSceneRead {
  NamosimScene scene;
  std::string error;  // names the element: "element <path> 'robot_0' (line 3): path data at ..."
};

/// `tolerance`: root user units to which robot and goal outlines are flattened.
NamosimSceneRead readNamosimScene(const SvgDocument& document, double tolerance);

}  // namespace ifar::sim
