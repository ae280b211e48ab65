// One system: the headless runner and the daemons run the same node cores, so the same inputs give the
// same outputs. The runner drives the demo room (a light box pushed out of the doorway; a heavy one found
// unpushable and driven round) and records every message its nodes exchange as an LCM log. That log's planner
// and executive inputs, with their receive times, are then fed through the daemons' own wiring
// (PlannerDaemon, ExecutiveDaemon) on an in-process LCM bus (memq://) with a manual clock: what the daemons
// publish must be what the runner's nodes published, byte for byte (planner stage timings aside: they are
// wall-clock measurements).

#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include "bus/run_loop.hpp"
#include "common/lcm_log/log_reader.hpp"
#include "executive/daemon/executive_daemon.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "planner/daemon/planner_daemon.hpp"
#include "sim/world/world_file.hpp"
#include "system/run_config.hpp"
#include "system/scenario_runner.hpp"
#include "system/simulated_stack.hpp"
#include "testing/temporary_directory.hpp"
#include "tools/replay_test/log_clock_feed.hpp"

namespace ifar::runner {
namespace {

const std::string kSourceDir = IFAR_SOURCE_DIR;

/// A run's log, read back: every event in order.
std::vector<lcm_log::LogEvent> readLog(const std::string& path)
{
  std::vector<lcm_log::LogEvent> events;
  lcm_log::LogReader reader = lcm_log::LogReader::open(path);
  EXPECT_EQ(reader.openError(), "");
  lcm_log::LogEvent event;
  while (reader.next(event)) {
    events.push_back(event);
  }
  EXPECT_TRUE(reader.clean()) << reader.problemSummary();
  return events;
}

/// What a node published, per channel, as encoded bytes in order.
using Publications = std::map<std::string, std::vector<std::vector<std::uint8_t>>>;

Publications publicationsIn(const std::vector<lcm_log::LogEvent>& events,
                            const std::set<std::string>& channels)
{
  Publications publications;
  for (const lcm_log::LogEvent& event : events) {
    if (channels.count(event.channel) > 0) {
      publications[event.channel].push_back(event.data);
    }
  }
  return publications;
}

/// PLANNER_STATUS without its stage timings, which measure this process's wall clock.
std::vector<std::uint8_t> withoutTimings(const std::vector<std::uint8_t>& bytes)
{
  planner_status_t status;
  EXPECT_GE(status.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  status.perception_ms = status.local_graph_ms = status.merge_ms = 0.0F;
  status.interaction_ms = status.search_ms = status.total_ms = 0.0F;
  std::vector<std::uint8_t> encoded(static_cast<std::size_t>(status.getEncodedSize()));
  status.encode(encoded.data(), 0, static_cast<int>(encoded.size()));
  return encoded;
}

/// Replays `events` on `inputs` into a daemon on `loop` whose manual clock reads `clock`: at each logged
/// time, first the inputs of that time, then the timers due, as the runner steps (LogClockFeed). Returns what
/// the daemon published on `outputs`.
Publications replay(bus::RunLoop& loop, std::int64_t& clock, const std::vector<lcm_log::LogEvent>& events,
                    const std::set<std::string>& inputs, const std::set<std::string>& outputs)
{
  Publications published;
  for (const std::string& channel : outputs) {
    loop.subscribeRaw(channel, [&published](const lcm::ReceiveBuffer* buffer, const std::string& name) {
      const auto* data = static_cast<const std::uint8_t*>(buffer->data);
      published[name].emplace_back(data, data + buffer->data_size);
    });
  }
  replay_test::LogClockFeed feed(inputs, {[&clock](std::int64_t utime) { clock = utime; },
                                          [&loop](const lcm_log::LogEvent& event) {
                                            loop.lcm().publish(event.channel, event.data.data(),
                                                               static_cast<unsigned>(event.data.size()));
                                          },
                                          [&loop](std::int64_t /*utime*/) {
                                            loop.deliverPending();
                                            loop.runDueTimers();
                                            loop.deliverPending();
                                          }});
  for (const lcm_log::LogEvent& event : events) {
    feed.add(event);
  }
  feed.finish();
  return published;
}

std::shared_ptr<spdlog::logger> silentLogger(const std::string& name)
{
  return std::make_shared<spdlog::logger>(name, std::make_shared<spdlog::sinks::null_sink_mt>());
}

/// The planner daemon's publications for the log's planner inputs.
Publications plannerDaemonReplay(const RunRequest& request, const std::vector<lcm_log::LogEvent>& events,
                                 const std::set<std::string>& outputs)
{
  const planner::PlannerChannels& channels = request.planner_node.channels;
  const std::set<std::string> inputs{
      channels.velodyne_packet, channels.pose, channels.goal, channels.affordance, channels.blocked_passage,
      channels.detected_objects};
  std::int64_t clock = request.sim.simulator.epoch_utime;
  bus::RunLoop loop("memq://", silentLogger("planner_identity_loop"), [&clock] { return clock; });
  const planner::PlannerDaemon daemon(loop, request.planner_node,
                                      planner::Planner(runnerPlannerSettings(request)),
                                      silentLogger("planner_identity"), planner::WorkerThreading::InLine);
  return replay(loop, clock, events, inputs, outputs);
}

/// The executive daemon's publications for the log's executive inputs.
Publications executiveDaemonReplay(const RunRequest& request, const std::vector<lcm_log::LogEvent>& events,
                                   const std::set<std::string>& outputs)
{
  const std::set<std::string> inputs{executive::kPoseChannel,        request.obstacles.packet_channel,
                                     executive::kPathChannel,        executive::kForceChannel,
                                     executive::kMotorStatusChannel, executive::kOdometryChannel,
                                     executive::kEStopChannel};
  std::int64_t clock = request.sim.simulator.epoch_utime;
  bus::RunLoop loop("memq://", silentLogger("executive_identity_loop"), [&clock] { return clock; });
  const executive::ExecutiveDaemon daemon(loop, request.executive, request.obstacles, request.vehicle,
                                          silentLogger("executive_identity"));
  return replay(loop, clock, events, inputs, outputs);
}

struct IdentityRun {
  const char* world_file;  // under config/worlds
  int pushes;              // completed by the run
  int affordance_updates;  // AFFORDANCE the executive sent (each one a planner update job)
};

class NodeIdentity : public ::testing::TestWithParam<IdentityRun> {};

// One run serves every check of a world: it is the expensive part.
TEST_P(NodeIdentity, ARunsRecordedMessagesThroughTheDaemonsGiveTheRunnersOutputs)
{
  const IdentityRun& run = GetParam();
  const test_support::TemporaryDirectory directory("node_identity");
  RunRequest request = loadRunSettings(kSourceDir + "/config");
  const sim::WorldResult world = sim::loadWorldFile(kSourceDir + "/config/worlds/" + run.world_file);
  ASSERT_TRUE(world.ok()) << world.error();
  request.world = world.world();
  request.goal = geometry::Point(8.0, 26.0);
  request.max_sim_time_s = 200.0;
  request.log_path = (directory.path() / "run.lcmlog").string();
  const RunSummary summary = runScenario(request, {});
  ASSERT_TRUE(summary.arrived) << summary.reason;
  EXPECT_EQ(summary.pushes, run.pushes);
  EXPECT_EQ(summary.affordance_updates, run.affordance_updates);
  const std::vector<lcm_log::LogEvent> events = readLog(request.log_path);
  std::set<std::string> channels;
  for (const lcm_log::LogEvent& event : events) {
    channels.insert(event.channel);
  }
  for (const char* channel :
       {"VELODYNE_PACKET", "POSE", "GOAL", "GLOBAL_PATH", "PLANNER_STATUS", "FORCE", "MOTOR_STATUS",
        "ODOMETRY", "VELOCITY_CMD", "EXEC_STATUS", "CAN_VEHICLE", "SIM_GROUND_TRUTH"}) {
    EXPECT_EQ(channels.count(channel), 1U) << channel << " missing from the run's log";
  }

  {
    SCOPED_TRACE("planner");
    const planner::PlannerChannels& planner_channels = request.planner_node.channels;
    const std::set<std::string> outputs{planner_channels.global_path, planner_channels.planner_status};
    Publications published = plannerDaemonReplay(request, events, outputs);
    Publications expected = publicationsIn(events, outputs);
    const auto& paths = expected[planner_channels.global_path];
    const auto& statuses = expected[planner_channels.planner_status];
    ASSERT_GT(paths.size(), 100U);
    EXPECT_EQ(published[planner_channels.global_path].size(), paths.size());
    EXPECT_TRUE(published[planner_channels.global_path] == paths);
    ASSERT_EQ(published[planner_channels.planner_status].size(), statuses.size());
    for (std::size_t index = 0; index < statuses.size(); ++index) {
      ASSERT_EQ(withoutTimings(published[planner_channels.planner_status][index]),
                withoutTimings(statuses[index]))
          << "PLANNER_STATUS " << index;
    }
  }
  {
    SCOPED_TRACE("executive");
    const std::set<std::string> outputs{executive::kCommandChannel, executive::kStatusChannel,
                                        executive::kAffordanceChannel, executive::kBlockedPassageChannel};
    Publications published = executiveDaemonReplay(request, events, outputs);
    Publications expected = publicationsIn(events, outputs);
    ASSERT_GT(expected[executive::kCommandChannel].size(), 1000U);
    for (const char* channel : {executive::kCommandChannel, executive::kStatusChannel}) {
      const std::vector<std::vector<std::uint8_t>>& mine = published[channel];
      const std::vector<std::vector<std::uint8_t>>& theirs = expected[channel];
      ASSERT_EQ(mine.size(), theirs.size()) << channel;
      for (std::size_t index = 0; index < theirs.size(); ++index) {
        ASSERT_EQ(mine[index], theirs[index]) << channel << " message " << index;
      }
    }
    EXPECT_EQ(published[executive::kAffordanceChannel], expected[executive::kAffordanceChannel]);
    EXPECT_EQ(published[executive::kBlockedPassageChannel], expected[executive::kBlockedPassageChannel]);
    EXPECT_EQ(expected[executive::kAffordanceChannel].size(),
              static_cast<std::size_t>(run.affordance_updates));
  }
}

// The light box pushed out of the doorway; a box too heavy to push, found so by touch (AFFORDANCE), and the
// way round the room replanned at once.
INSTANTIATE_TEST_SUITE_P(DemoRoom, NodeIdentity,
                         ::testing::Values(IdentityRun{"demo_room.yaml", 1, 0},
                                           IdentityRun{"demo_room_heavy.yaml", 0, 1}),
                         [](const ::testing::TestParamInfo<IdentityRun>& param_info) {
                           return param_info.param.affordance_updates == 0 ? std::string("LightBox")
                                                                           : std::string("HeavyBox");
                         });

}  // namespace
}  // namespace ifar::runner
