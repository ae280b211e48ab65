// ifar-render-graph (`ifar render-graph`): the last DV_GRAPH and GLOBAL_PATH of an LCM log as a PNG, with
// the run drawn over it (trajectory, push plans, object tracks).

#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "viz/graph_render.hpp"

int main(int argc, char** argv)
{
  CLI::App app{
      "Draws the last DV_GRAPH and GLOBAL_PATH of an LCM log as a PNG. Background polygons red, "
      "movable green, graph edges, path blue; with the vehicle's trajectory (POSE) black, the push plans "
      "magenta and the objects' tracks (SIM_GROUND_TRUTH, when simulated) dark green"};
  std::string log_path;
  std::string output = "graph.png";
  std::string graph_channel = "DV_GRAPH";
  std::string path_channel = "GLOBAL_PATH";
  std::string pose_channel = "POSE";
  std::string truth_channel = "SIM_GROUND_TRUTH";
  ifar::viz::RenderOptions options;
  app.add_option("log", log_path, "LCM log file")->required();
  app.add_option("-o,--output", output, "PNG to write")->capture_default_str();
  app.add_option("--graph-channel", graph_channel, "channel of the dv_graph_t messages")
      ->capture_default_str();
  app.add_option("--path-channel", path_channel, "channel of the path_t messages")->capture_default_str();
  app.add_option("--pose-channel", pose_channel, "channel of the pose_t messages (trajectory)")
      ->capture_default_str();
  app.add_option("--truth-channel", truth_channel, "channel of the simulator's world_state_t (object tracks)")
      ->capture_default_str();
  app.add_option("--resolution", options.metres_per_pixel, "metres per pixel")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  std::string window_text;
  app.add_option("--window", window_text, "draw only this world rectangle: X0,Y0,X1,Y1 in metres");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  if (!window_text.empty()) {
    options.window = ifar::viz::parseWindow(window_text);
    if (!options.window) {
      std::cerr << "error: --window: expected " << ifar::viz::kWindowFormat << ", got '" << window_text
                << "'\n";
      return ifar::common::kBadInputExitCode;
    }
  }

  const ifar::viz::LastMessages last =
      ifar::viz::readLastMessages(log_path, graph_channel, path_channel, pose_channel, truth_channel);
  if (!last.error.empty()) {
    std::cerr << "error: " << last.error << "\n";
    return ifar::common::kBadInputExitCode;
  }
  if (!last.log_problems.empty()) {
    std::cerr << "warning: " << log_path
              << " is corrupt, drawn from the events that could be read: " << last.log_problems << "\n";
  }
  if (last.undecodable > 0) {
    std::cerr << "warning: " << log_path << ": " << last.undecodable
              << " messages did not decode and were skipped\n";
  }
  if (!last.graph) {
    std::cerr << "error: " << log_path << ": no decodable message on channel " << graph_channel << "\n";
    return ifar::common::kBadInputExitCode;
  }
  const ifar::viz::Canvas canvas = ifar::viz::renderGraph(*last.graph, last.path, options, last.run);
  const std::string error = canvas.writePng(output);
  if (!error.empty()) {
    std::cerr << "error: " << error << "\n";
    return ifar::common::kOutputFailedExitCode;
  }
  std::cout << output << ": " << last.graph->num_polygons << " polygons, " << last.graph->num_vertices
            << " vertices, " << last.graph->num_edges << " edges, path "
            << (last.path && last.path->valid ? std::to_string(last.path->num_waypoints) + " waypoints"
                                              : "none")
            << ", trajectory " << last.run.trajectory.size() << " points, " << last.run.push_plans.size()
            << " push plans, " << last.run.object_tracks.size() << " moved objects\n";
  return 0;
}
