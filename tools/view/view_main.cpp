// ifar view: a live view of the stack in any browser on the vehicle's network. Subscribes to every LCM
// channel, decodes each project type by its schema (as ifar echo does) and serves the page (built in) with a
// WebSocket that streams the messages as JSON; the page draws the DV-graph, path, push plans, vehicle,
// trajectory, goals, the executive's mode and findings, the force and every daemon's health. The same on
// `ifar sim` or the whole stack, and on `ifar replay` of a log. Foxglove and Lichtblick connect at
// ws://HOST:PORT/foxglove (the Foxglove WebSocket protocol, foxglove_protocol.hpp).

#include <cstdio>
#include <filesystem>
#include <string>

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "bus/lcm_url.hpp"
#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/json_text.hpp"
#include "common/vehicle.hpp"
#include "lcmtypes/message_schema.hpp"
#include "tools/view/view_hub.hpp"
#include "tools/view/web_assets.hpp"
#include "tools/view/web_server.hpp"

namespace {

// Held-back messages and pages' arrivals are handled this often.
constexpr double kTickPeriodS = 0.05;

struct ViewOptions {
  std::string address = "0.0.0.0";
  int port = 8080;
  std::string lcm_url;
  std::string vehicle_config = "config/vehicle.yaml";
  double max_rate_hz = 20.0;
  std::string web_root;
};

int fail(int exit_code, const std::string& message)
{
  std::fprintf(stderr, "ifar view: error: %s\n", message.c_str());
  return exit_code;
}

std::string number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string helloLine(const ifar::common::VehicleSettings& vehicle, const std::string& lcm_url,
                      double max_rate_hz)
{
  return "{\"view\":\"hello\",\"server\":\"ifar view\",\"lcm_url\":" + ifar::common::jsonString(lcm_url) +
         ",\"max_rate_hz\":" + number(max_rate_hz) +
         ",\"vehicle\":{\"length_m\":" + number(vehicle.length_m) +
         ",\"width_m\":" + number(vehicle.width_m) + ",\"bumper_width_m\":" + number(vehicle.bumper_width_m) +
         ",\"wheel_track_m\":" + number(vehicle.wheel_track_m) +
         ",\"lidar_x_m\":" + number(vehicle.lidar_x_m) + "}}";
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "A live view in the browser: serves a page (built in, no network needed) and streams every LCM message "
      "of a project type to it over a WebSocket; it draws the DV-graph, path, push plans, vehicle, "
      "trajectory, "
      "goal, the executive's mode, affordances, force and every daemon's heartbeat. Open the printed URL. "
      "Foxglove or Lichtblick: open a Foxglove WebSocket connection to ws://HOST:PORT/foxglove (subprotocol "
      "foxglove.websocket.v1): every forwarded channel is advertised, JSON with a JSON Schema, thinned as "
      "for "
      "the page (docs/view.md)."};
  ViewOptions options;
  app.add_option("--port", options.port,
                 "HTTP port: the page, its /ws and Foxglove's /foxglove (0: any free port, printed at start)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  app.add_option("--address", options.address,
                 "address to listen on (0.0.0.0: every interface, so any browser on the vehicle's network; "
                 "127.0.0.1: this host only)")
      ->capture_default_str();
  app.add_option("--lcm-url", options.lcm_url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  CLI::Option* vehicle_option =
      app.add_option("--vehicle", options.vehicle_config, "vehicle.yaml: the footprint drawn at each pose")
          ->capture_default_str();
  app.add_option(
         "--max-rate-hz", options.max_rate_hz,
         "channels faster than this are thinned to it for the page and Foxglove clients (the last message of "
         "a burst always goes); heartbeats, graphs, goals and the executive's reports are never thinned")
      ->check(ifar::common::atLeast(0.1))
      ->capture_default_str();
  app.add_option("--web-root", options.web_root,
                 "serve the page's files from this folder instead of the built-in copy (page development)")
      ->check(CLI::ExistingDirectory);
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  ifar::common::VehicleSettings vehicle;
  if (vehicle_option->count() > 0 || std::filesystem::exists(options.vehicle_config)) {
    try {
      const ifar::common::ConfigNode root = ifar::common::ConfigNode::loadFile(options.vehicle_config);
      vehicle = ifar::common::loadVehicleSettings(root);
    } catch (const ifar::common::ConfigError& error) {
      return fail(ifar::common::kBadInputExitCode, std::string("--vehicle: ") + error.what());
    }
  } else {
    std::fprintf(stderr,
                 "ifar view: %s not found: the footprint has the built-in vehicle's size (%.2f x %.2f m)\n",
                 options.vehicle_config.c_str(), vehicle.length_m, vehicle.width_m);
  }

  try {
    auto logger = spdlog::stderr_logger_mt("view");
    // The loop first: it blocks SIGINT/SIGTERM for the threads started after it (civetweb's among them).
    ifar::bus::RunLoop loop(options.lcm_url, logger);
    ifar::view::WebServerSettings server_settings;
    server_settings.address = options.address;
    server_settings.port = options.port;
    server_settings.assets = ifar::view::webAssets();
    server_settings.asset_directory = options.web_root;
    server_settings.sockets = {
        {"/ws", ""}, {std::string(ifar::view::kFoxglovePath), std::string(ifar::view::kFoxgloveSubprotocol)}};
    ifar::view::WebServer server(server_settings);

    ifar::view::FeedSettings feed_settings;
    feed_settings.max_rate_hz = options.max_rate_hz;
    const std::string lcm_url = ifar::bus::resolveLcmUrl(options.lcm_url);
    const std::string shown_lcm_url = lcm_url.empty() ? std::string(ifar::bus::kLcmDefaultUrl) : lcm_url;
    ifar::view::FoxgloveServerInfo foxglove_info;
    foxglove_info.metadata = {{"lcm_url", shown_lcm_url}, {"max_rate_hz", number(options.max_rate_hz)}};
    ifar::view::ViewHub hub(
        ifar::lcmtypes::messageSchema(), feed_settings,
        helloLine(vehicle, shown_lcm_url, options.max_rate_hz),
        [&server](ifar::view::ClientId client, const std::vector<ifar::view::WebFrame>& frames) {
          server.send(client, frames);
        },
        foxglove_info);
    loop.subscribeRaw(".*", [&hub](const lcm::ReceiveBuffer* buffer, const std::string& channel) {
      hub.onMessage(channel,
                    ifar::common::ByteView(static_cast<const std::uint8_t*>(buffer->data), buffer->data_size),
                    buffer->recv_utime);
    });
    loop.every(kTickPeriodS, [&loop, &hub, &server] {
      for (const ifar::view::ClientEvent& event : server.takeEvents()) {
        if (event.kind == ifar::view::ClientEvent::Kind::kJoined) {
          spdlog::get("view")->info(
              "{} from {}",
              event.endpoint == ifar::view::kFoxglovePath ? "Foxglove client connected" : "page opened",
              event.text);
        }
        hub.onClientEvent(event);
      }
      hub.tick(loop.now());
    });
    const std::string shown_address = options.address == "0.0.0.0" ? "127.0.0.1" : options.address;
    std::printf(
        "ifar view: open http://%s:%d/ in a browser%s\n", shown_address.c_str(), server.port(),
        options.address == "0.0.0.0" ? " (or this host's name or address from the vehicle's network)" : "");
    std::printf("ifar view: Foxglove: ws://%s:%d%s\n", shown_address.c_str(), server.port(),
                std::string(ifar::view::kFoxglovePath).c_str());
    std::printf("ifar view: listening on %s:%d, LCM %s\n", options.address.c_str(), server.port(),
                lcm_url.empty() ? "default URL" : lcm_url.c_str());
    std::fflush(stdout);
    return loop.run();
  } catch (const std::exception& error) {
    return fail(1, error.what());
  }
}
