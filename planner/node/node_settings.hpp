#pragma once
// The planner node's own settings: the `daemon:` section of config/planner.yaml (rate, channels, input
// ages), read by the daemon and the headless runner alike. The perception and graph sections are read by
// their own loaders.

#include <set>
#include <string>

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner.hpp"

namespace ifar::planner {

struct PlannerChannels {
  std::string velodyne_packet = "VELODYNE_PACKET";
  std::string pose = "POSE";
  std::string goal = "GOAL";
  std::string detected_objects = "DETECTED_OBJECTS";
  std::string affordance = "AFFORDANCE";
  std::string blocked_passage = "BLOCKED_PASSAGE";
  std::string dv_graph = "DV_GRAPH";
  std::string global_path = "GLOBAL_PATH";
  std::string planner_status = "PLANNER_STATUS";
  std::string journal = "PLANNER_JOURNAL";

  /// The node's inputs: what the daemon subscribes to for it (and journals).
  std::set<std::string> inputs() const
  {
    return {velodyne_packet, pose, goal, detected_objects, affordance, blocked_passage};
  }
};

struct NodeSettings {
  double rate_hz = 2.5;             // graph updates and publications per second (the paper's 2.5 Hz)
  double path_resend_hz = 20.0;     // the last GLOBAL_PATH is sent again this often (fresh utime)
  InputSettings input;              // stale and future limits for packets and poses
  double detector_max_age_s = 1.0;  // detector outlines older than this fall back to reflectivity
  double arrival_radius_m = 0.5;    // the vehicle this close to the goal has arrived
  std::string vehicle_config = "vehicle.yaml";  // top-level key `vehicle_config`
  std::string prior_graph;                      // saved global graph to start from; empty = none
  int data_port = 2368;  // velodyne_packet_t.port of data packets; others (position packets) carry no points
  PlannerChannels channels;
};

/// planner.yaml's top-level `vehicle_config` and `daemon:` keys, every one optional.
const common::ParameterTable<NodeSettings>& nodeParameters();

/// Reads the top-level `vehicle_config` and the `daemon` child of `root` (every key optional, with the
/// defaults above; rates and ages must be positive) and rejects unknown keys inside it. Throws
/// common::ConfigError naming file and key.
NodeSettings loadNodeSettings(const common::ConfigNode& root);

/// The whole planner.yaml: perception, graph, interaction and daemon sections (the vehicle is read
/// separately from daemon.vehicle_config; the interaction pusher comes from it). Unknown keys anywhere
/// throw common::ConfigError.
struct PlannerConfig {
  PlannerSettings planner;  // vehicle left at its defaults
  NodeSettings node;        // the `daemon:` section
};
PlannerConfig loadPlannerConfig(const common::ConfigNode& root);

/// planner.yaml `interaction:` keys that are the planner's, not the interaction planner's (`enabled`).
const common::ParameterTable<PlannerSettings>& plannerInteractionParameters();

/// The effective planner.yaml as YAML with every key's meaning as a comment (--print-config).
std::string plannerConfigYaml(const PlannerConfig& config);

}  // namespace ifar::planner
