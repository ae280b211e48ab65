#include "planner/node/node_settings.hpp"

#include <cmath>

#include "planner/graph/settings.hpp"
#include "planner/interaction/settings_loader.hpp"
#include "planner/perception/perception_settings.hpp"

namespace ifar::planner {

namespace {

using Range = common::ParameterRange;

template <typename Member>
void addChannel(common::ParameterTable<NodeSettings>& table, const std::string& key, Member member,
                const std::string& meaning)
{
  table.add(
      "daemon.channels." + key, [member](auto& s) -> auto& { return s.channels.*member; }, "",
      Range::nonEmpty(), meaning);
}

common::ParameterTable<NodeSettings> makeNodeParameters()
{
  using S = NodeSettings;
  auto table =
      common::ParameterTable<S>()
          .add("vehicle_config", &S::vehicle_config, "", Range::nonEmpty(),
               "vehicle dimensions, lidar mount and filter; a relative path is beside this file, else on the "
               "configuration search path")
          .add("daemon.rate_hz", &S::rate_hz, "Hz", Range::positive(),
               "graph updates and publications per second")
          .add("daemon.path_resend_hz", &S::path_resend_hz, "Hz", Range::positive(),
               "the last GLOBAL_PATH again (fresh utime) between updates: liveness for the executive")
          .add(
              "daemon.stale_input_age_s", [](auto& s) -> auto& { return s.input.stale_input_age_s; }, "s",
              Range::positive(), "a scan farther than this from every pose cannot be placed")
          .add(
              "daemon.max_future_s", [](auto& s) -> auto& { return s.input.max_future_s; }, "s",
              Range::positive(), "packets and poses stamped later than now + this are refused")
          .add(
              "daemon.pose_history_s", [](auto& s) -> auto& { return s.input.pose_history_s; }, "s",
              Range::positive(), "poses kept for interpolating the vehicle over a scan")
          .add("daemon.detector_max_age_s", &S::detector_max_age_s, "s", Range::positive(),
               "older DETECTED_OBJECTS outlines fall back to reflectivity")
          .add("daemon.arrival_radius_m", &S::arrival_radius_m, "m", Range::positive(),
               "the vehicle this close to the goal has arrived: PLANNER_STATUS says so (the path is still "
               "published); the executive's goal_tolerance_m decides where the vehicle stops")
          .add("daemon.prior_graph", &S::prior_graph, "", Range::any(),
               "a saved global graph (graph_file.hpp) to start from; \"\" = none")
          .add(
              "daemon.data_port", &S::data_port, "", Range::between(1, 65535),
              "VELODYNE_PACKET port of data packets (the driver's data_port); other packets carry no points");
  addChannel(table, "velodyne_packet", &PlannerChannels::velodyne_packet,
             "lidar packets (velodyne_packet_t)");
  addChannel(table, "pose", &PlannerChannels::pose, "vehicle pose (pose_t)");
  addChannel(table, "goal", &PlannerChannels::goal, "goal to plan to");
  addChannel(table, "detected_objects", &PlannerChannels::detected_objects,
             "optional external movable-object detector (object_polygons_t)");
  addChannel(table, "affordance", &PlannerChannels::affordance, "the executive's affordance updates");
  addChannel(table, "blocked_passage", &PlannerChannels::blocked_passage,
             "passages the executive could not get through (blocked_passage_t)");
  addChannel(table, "dv_graph", &PlannerChannels::dv_graph, "the published DV-graph");
  addChannel(table, "global_path", &PlannerChannels::global_path, "the published path");
  addChannel(table, "planner_status", &PlannerChannels::planner_status, "the planner's status");
  addChannel(table, "journal", &PlannerChannels::journal,
             "what the loop handed the node, for ifar replay-test (node_journal_t)");
  return table;
}

}  // namespace

const common::ParameterTable<NodeSettings>& nodeParameters()
{
  static const auto table = makeNodeParameters();
  return table;
}

const common::ParameterTable<PlannerSettings>& plannerInteractionParameters()
{
  static const auto table = common::ParameterTable<PlannerSettings>().add(
      "enabled", &PlannerSettings::interaction_enabled, "", Range::any(),
      "false = FAR mode: movable objects are plain obstacles, no pushes");
  return table;
}

NodeSettings loadNodeSettings(const common::ConfigNode& root)
{
  NodeSettings settings;
  nodeParameters().read(root, settings);
  if (root.has("daemon")) {
    root.child("daemon").rejectUnknownKeys();
  }
  return settings;
}

PlannerConfig loadPlannerConfig(const common::ConfigNode& root)
{
  PlannerConfig config;
  config.planner.perception = perception::loadPerceptionSettings(root);
  config.planner.graph =
      root.has("graph") ? graph::loadGraphSettings(root.child("graph")) : graph::GraphSettings{};
  config.node = loadNodeSettings(root);
  config.planner.arrival_radius_m = config.node.arrival_radius_m;
  if (root.has("interaction")) {
    const common::ConfigNode interaction = root.child("interaction");
    plannerInteractionParameters().read(interaction, config.planner);
    // The pusher part is derived from the vehicle again when the Planner is built.
    config.planner.interaction = interaction::loadInteractionSettings(interaction, common::VehicleSettings{});
  }
  root.rejectUnknownKeys();
  return config;
}

std::string plannerConfigYaml(const PlannerConfig& config)
{
  common::ConfigDump dump;
  perception::perceptionParameters().dump(config.planner.perception, "perception", dump);
  graph::graphParameters().dump(config.planner.graph, "graph", dump);
  plannerInteractionParameters().dump(config.planner, "interaction", dump);
  interaction::interactionParameters().dump(config.planner.interaction, "interaction", dump);
  nodeParameters().dump(config.node, "", dump);
  return dump.yaml();
}

}  // namespace ifar::planner
