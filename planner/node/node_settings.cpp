#include "planner/node/node_settings.hpp"

#include <cmath>

#include "planner/graph/settings.hpp"
#include "planner/interaction/settings_loader.hpp"
#include "planner/perception/perception_settings.hpp"

namespace ifar::planner {

namespace {

double positive(const common::ConfigNode& node, const std::string& key, double fallback)
{
  const double value = node.optional<double>(key, fallback);
  if (!std::isfinite(value) || value <= 0.0) {
    node.fail(key, "must be a positive number");
  }
  return value;
}

std::string channel(const common::ConfigNode& node, const std::string& key, const std::string& fallback)
{
  std::string value = node.optional<std::string>(key, fallback);
  if (value.empty()) {
    node.fail(key, "channel name must not be empty");
  }
  return value;
}

}  // namespace

NodeSettings loadNodeSettings(const common::ConfigNode& root)
{
  NodeSettings settings;
  // Top level, as in sim.yaml: the file every daemon reads the vehicle from.
  settings.vehicle_config = root.optional<std::string>("vehicle_config", settings.vehicle_config);
  if (settings.vehicle_config.empty()) {
    root.fail("vehicle_config", "must name the vehicle settings file");
  }
  if (!root.has("daemon")) {
    return settings;
  }
  const common::ConfigNode node = root.child("daemon");
  settings.rate_hz = positive(node, "rate_hz", settings.rate_hz);
  settings.path_resend_hz = positive(node, "path_resend_hz", settings.path_resend_hz);
  settings.input.stale_input_age_s = positive(node, "stale_input_age_s", settings.input.stale_input_age_s);
  settings.input.max_future_s = positive(node, "max_future_s", settings.input.max_future_s);
  settings.input.pose_history_s = positive(node, "pose_history_s", settings.input.pose_history_s);
  settings.detector_max_age_s = positive(node, "detector_max_age_s", settings.detector_max_age_s);
  settings.arrival_radius_m = positive(node, "arrival_radius_m", settings.arrival_radius_m);
  settings.prior_graph = node.optional<std::string>("prior_graph", settings.prior_graph);
  settings.data_port = node.optional<int>("data_port", settings.data_port);
  if (settings.data_port < 1 || settings.data_port > 65535) {
    node.fail("data_port", "must be a UDP port, 1 to 65535");
  }
  if (node.has("channels")) {
    const common::ConfigNode channels = node.child("channels");
    PlannerChannels& out = settings.channels;
    out.velodyne_packet = channel(channels, "velodyne_packet", out.velodyne_packet);
    out.pose = channel(channels, "pose", out.pose);
    out.goal = channel(channels, "goal", out.goal);
    out.detected_objects = channel(channels, "detected_objects", out.detected_objects);
    out.affordance = channel(channels, "affordance", out.affordance);
    out.blocked_passage = channel(channels, "blocked_passage", out.blocked_passage);
    out.dv_graph = channel(channels, "dv_graph", out.dv_graph);
    out.global_path = channel(channels, "global_path", out.global_path);
    out.planner_status = channel(channels, "planner_status", out.planner_status);
  }
  node.rejectUnknownKeys();
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
    config.planner.interaction_enabled =
        interaction.optional<bool>("enabled", config.planner.interaction_enabled);
    // The pusher part is derived from the vehicle again when the Planner is built.
    config.planner.interaction = interaction::loadInteractionSettings(interaction, common::VehicleSettings{});
  }
  root.rejectUnknownKeys();
  return config;
}

}  // namespace ifar::planner
