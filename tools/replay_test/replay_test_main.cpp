// ifar replay-test LOG --node planner|executive: replays a log's inputs into one node's core on the log's own
// clock (node_replay.hpp) and compares what it publishes with what the log recorded, message by message in
// order, member by member. Exit 0 when they agree, 1 at a difference (the first one printed, named by
// channel, message, log time and member), 2 on bad input (command line, config, a corrupt log, a log without
// the node's inputs or outputs).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/daemon_main.hpp"
#include "common/lcm_log/log_reader.hpp"
#include "common/lcm_log/strict_event_reader.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/node/executive_node.hpp"
#include "executive/obstacles/local_obstacles.hpp"
#include "ifar/planner_status_t.hpp"
#include "lcmtypes/checked_decode.hpp"
#include "lcmtypes/message_schema.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/node/node_settings.hpp"
#include "system/run_config.hpp"
#include "tools/echo/message_value.hpp"
#include "tools/replay_test/journal_feed.hpp"
#include "tools/replay_test/log_clock_feed.hpp"
#include "tools/replay_test/message_comparison.hpp"
#include "tools/replay_test/node_replay.hpp"

namespace {

using ifar::common::kBadInputExitCode;
using ifar::replay_test::Published;

// A log whose first event comes this soon after the runner's clock origin is a log of `ifar run`.
constexpr std::int64_t kRunnerLogWindowUs = 1'000'000;
// The planner's stage timings measure the wall clock of the process that ran it: never the same twice.
const std::set<std::string> kWallClockMembers = {
    "planner_status_t.perception_ms",  "planner_status_t.local_graph_ms", "planner_status_t.merge_ms",
    "planner_status_t.interaction_ms", "planner_status_t.search_ms",      "planner_status_t.total_ms"};

struct Options {
  std::string log;
  std::string node;
  std::string config_dir = "config";
  std::vector<std::string> sets;
  double tolerance = 0.0;
  std::optional<std::int64_t> start_utime;
  bool node_config_from_dir = false;
};

int fail(int exit_code, const std::string& message)
{
  std::fprintf(stderr, "ifar replay-test: error: %s\n", message.c_str());
  return exit_code;
}

/// The node's own file in the config directory.
std::string nodeFile(const Options& options)
{
  return (std::filesystem::path(options.config_dir) /
          (options.node == "planner" ? "planner.yaml" : "executive.yaml"))
      .string();
}

/// The node's own configuration with the --set overrides, read by the node's loaders into `request` (the
/// other files as loadRunSettings read them): `journal_settings` when given (what the daemon ran with), else
/// its file in the config directory. Throws common::ConfigError.
void applyNodeFile(const Options& options, ifar::runner::RunRequest& request,
                   const std::string& journal_settings = {}, const std::string& journal_name = {})
{
  ifar::common::ConfigNode root = journal_settings.empty()
                                      ? ifar::common::ConfigNode::loadFile(nodeFile(options))
                                      : ifar::common::ConfigNode::loadString(journal_settings, journal_name);
  for (const std::string& assignment : options.sets) {
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw ifar::common::ConfigError("--set " + assignment + ": expected KEY=VALUE");
    }
    root.set(assignment.substr(0, equals), assignment.substr(equals + 1), "--set " + assignment);
  }
  ifar::common::readDaemonKeys(root);
  if (options.node == "planner") {
    const ifar::planner::PlannerConfig config = ifar::planner::loadPlannerConfig(root);
    request.planner = config.planner;
    request.planner.vehicle = request.vehicle;
    request.planner.interaction.pusher = ifar::interaction::PusherSettings::fromVehicle(request.vehicle);
    request.planner_node = config.node;
  } else {
    request.obstacles = ifar::executive::loadObstacleSettings(root.child("obstacles"));
    request.executive = ifar::executive::loadExecutiveSettings(root);
    root.rejectUnknownKeys();
  }
}

std::string secondsText(std::int64_t microseconds)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", static_cast<double>(microseconds) * 1e-6);
  return text;
}

std::string channelList(const std::set<std::string>& channels)
{
  std::string text;
  for (const std::string& channel : channels) {
    text += (text.empty() ? "" : ", ") + channel;
  }
  return text;
}

/// One channel's outcome: where its replayed messages first differ from the recorded ones.
struct ChannelOutcome {
  std::size_t recorded = 0;
  std::size_t replayed = 0;
  std::optional<std::size_t> first_difference;  // message index
  std::int64_t log_time_us = 0;                 // of that recorded message (or of the last one)
  std::string difference;
};

/// A message with the journal batch whose events made it (journal_feed.hpp).
struct Tagged {
  Published message;
  std::int64_t batch = 0;
};

/// When a recorded status at or before `until_us` shows the daemon's interaction planning past one of its
/// wall-clock budgets, why the replay (which has none) may differ from there; else empty.
std::string budgetNote(const ifar::planner::PlannerSettings& daemon, const std::vector<Tagged>& statuses,
                       std::int64_t until_us)
{
  const double budget_ms =
      std::min(daemon.interaction.loop.frame_budget_ms, daemon.interaction.search.time_budget_s * 1000.0);
  for (const Tagged& tagged : statuses) {
    if (tagged.message.utime > until_us) {
      break;
    }
    ifar::planner_status_t status;
    const std::vector<std::uint8_t>& bytes = tagged.message.bytes;
    if (ifar::lcmtypes::decodeLcm(status, bytes.data(), bytes.size()).ok() &&
        status.interaction_ms >= budget_ms) {
      char note[256];
      std::snprintf(note, sizeof note,
                    "the planner's interaction planning took %.1f ms at log time %s s, past its wall-clock "
                    "budget (%.1f ms); the replay has none, so from there on the two may differ",
                    status.interaction_ms, secondsText(tagged.message.utime).c_str(), budget_ms);
      return note;
    }
  }
  return {};
}

ChannelOutcome compareChannel(const ifar::echo::MessageTypes& types, const std::vector<Tagged>& recorded,
                              const std::vector<Tagged>& replayed,
                              const ifar::replay_test::ComparisonSettings& settings)
{
  ChannelOutcome outcome;
  outcome.recorded = recorded.size();
  outcome.replayed = replayed.size();
  for (std::size_t index = 0; index < recorded.size() && index < replayed.size(); ++index) {
    const std::string difference = ifar::replay_test::firstDifference(
        types,
        ifar::common::ByteView(recorded[index].message.bytes.data(), recorded[index].message.bytes.size()),
        ifar::common::ByteView(replayed[index].message.bytes.data(), replayed[index].message.bytes.size()),
        settings);
    if (!difference.empty()) {
      outcome.first_difference = index;
      outcome.log_time_us = recorded[index].message.utime;
      outcome.difference = difference;
      return outcome;
    }
  }
  if (recorded.size() != replayed.size()) {
    const std::size_t index = std::min(recorded.size(), replayed.size());
    outcome.first_difference = index;
    if (index < recorded.size()) {
      outcome.log_time_us = recorded[index].message.utime;
      outcome.difference = "recorded, not replayed (" + std::to_string(recorded.size()) + " recorded, " +
                           std::to_string(replayed.size()) + " replayed)";
    } else {
      outcome.log_time_us = replayed[index].message.utime;
      outcome.difference = "replayed, not recorded (" + std::to_string(recorded.size()) + " recorded, " +
                           std::to_string(replayed.size()) + " replayed)";
    }
  }
  return outcome;
}

int run(const Options& options)
{
  ifar::runner::RunRequest request;
  try {
    request = ifar::runner::loadRunSettings(options.config_dir);
    applyNodeFile(options, request);
  } catch (const ifar::common::ConfigError& error) {
    return fail(kBadInputExitCode, error.what());
  }

  ifar::lcm_log::LogReader log = ifar::lcm_log::LogReader::open(options.log);
  if (!log.openError().empty()) {
    return fail(kBadInputExitCode, log.openError());
  }
  ifar::lcm_log::StrictEventReader events(log);
  ifar::lcm_log::LogEvent event;
  if (!events.next(event)) {
    return fail(kBadInputExitCode, "'" + options.log + "' holds no event" +
                                       (events.problem().empty() ? "" : ": corrupt at " + events.problem()));
  }
  const std::int64_t first_utime = event.timestamp_us;
  const std::string journal_channel =
      options.node == "planner" ? request.planner_node.channels.journal : ifar::executive::kJournalChannel;
  // A log of the daemons holds their journals: the node is driven as its own loop drove it.
  const std::optional<ifar::node_journal_t> first_batch =
      options.start_utime ? std::nullopt : ifar::replay_test::firstJournalBatch(options.log, journal_channel);
  if (first_batch && first_batch->first_event != 0) {
    return fail(kBadInputExitCode, "'" + options.log + "' begins after the " + options.node +
                                       " had started: its journal (" + journal_channel +
                                       ") is logged from event " + std::to_string(first_batch->first_event) +
                                       " on; record from before the node starts");
  }
  // The daemon's own configuration, as its journal states it, unless asked for the directory's.
  std::string settings_origin = nodeFile(options);
  if (first_batch && !first_batch->settings.empty() && !options.node_config_from_dir) {
    settings_origin = "the " + options.node + "'s journal";
    try {
      applyNodeFile(options, request, first_batch->settings, settings_origin + " in " + options.log);
    } catch (const ifar::common::ConfigError& error) {
      return fail(kBadInputExitCode,
                  std::string(error.what()) + " (--node-config-from-dir reads " + options.config_dir + "'s)");
    }
  }
  if (!options.sets.empty()) {
    settings_origin += " with --set";
  }
  const std::int64_t origin = request.sim.simulator.epoch_utime;
  std::int64_t start_utime = first_utime;
  std::string start_reason =
      "the log's first event (no journal of the node in the log: its timers' phase is "
      "not recorded)";
  if (first_batch) {
    start_utime = first_batch->start_utime;
    start_reason = "the " + options.node + "'s journal on " + journal_channel + " (pid " +
                   std::to_string(first_batch->pid) + ")";
  } else if (options.start_utime) {
    start_utime = *options.start_utime;
    start_reason = "--start-utime";
  } else if (first_utime >= origin && first_utime < origin + kRunnerLogWindowUs) {
    start_utime = origin;
    start_reason = "the runner's clock origin (a log of ifar run)";
  }
  const ifar::replay_test::ReplayClock clock =
      first_batch ? ifar::replay_test::ReplayClock::kJournal : ifar::replay_test::ReplayClock::kRunner;

  std::unique_ptr<ifar::replay_test::NodeReplay> node;
  try {
    node = options.node == "planner" ? ifar::replay_test::plannerReplay(request, start_utime, true, clock)
                                     : ifar::replay_test::executiveReplay(request, start_utime);
  } catch (const std::invalid_argument& error) {
    return fail(kBadInputExitCode,
                std::string("the ") + options.node + " refuses the configuration: " + error.what());
  }
  const std::set<std::string> outputs = node->outputChannels();
  // Each output with the journal batch it belongs to (0 without a journal).
  std::map<std::string, std::vector<Tagged>> recorded;
  std::map<std::string, std::vector<Tagged>> replayed;
  std::optional<ifar::replay_test::JournalFeed> journal;
  const auto collect = [&] {
    const std::int64_t batch = journal ? journal->batch() : 0;
    for (Published& published : node->takePublished()) {
      published.utime -= first_utime;  // log time, for the report
      replayed[published.channel].push_back({std::move(published), batch});
    }
  };
  ifar::replay_test::LogClockFeed feed(
      node->inputChannels(), {[](std::int64_t) {},
                              [&node](const ifar::lcm_log::LogEvent& input) {
                                node->deliver(input.channel,
                                              ifar::common::ByteView(input.data.data(), input.data.size()),
                                              input.timestamp_us);
                              },
                              [&node, &collect](std::int64_t now_utime) {
                                node->runTimers(now_utime);
                                collect();
                              }});
  if (first_batch) {
    journal.emplace(
        journal_channel, *first_batch, node->inputChannels(),
        ifar::replay_test::JournalHooks{
            [&node, &collect](const std::string& channel, ifar::common::ByteView bytes, std::int64_t utime) {
              node->deliver(channel, bytes, utime);
              collect();
            },
            [&node, &collect](std::int8_t kind, std::int16_t code, std::int64_t utime) {
              node->journalEvent(kind, code, utime);
              collect();
            }});
  }
  do {
    if (outputs.count(event.channel) > 0) {
      recorded[event.channel].push_back({{event.channel, event.data, event.timestamp_us - first_utime},
                                         journal ? journal->batchesLogged() : 0});
    }
    if (journal) {
      journal->add(event);
    } else {
      feed.add(event);
    }
  } while (events.next(event));
  if (!events.problem().empty()) {
    return fail(kBadInputExitCode, "'" + options.log + "' is corrupt at " + events.problem());
  }
  std::string replayed_part;
  std::int64_t inputs_delivered = 0;
  if (journal) {
    journal->finish();
    inputs_delivered = journal->inputsDelivered();
    // Only what came of whole batches on both sides: the rest of the log has no journal to replay it by.
    const std::int64_t complete = journal->completeBatches();
    if (complete == 0) {
      return fail(kBadInputExitCode, "no batch of the " + options.node + "'s journal in '" + options.log +
                                         "' could be replayed: " +
                                         (journal->endReason().empty() ? "no events" : journal->endReason()));
    }
    for (auto* side : {&recorded, &replayed}) {
      for (auto& channel : *side) {
        auto& messages = channel.second;
        messages.erase(std::remove_if(messages.begin(), messages.end(),
                                      [complete](const Tagged& tagged) { return tagged.batch >= complete; }),
                       messages.end());
      }
    }
    replayed_part = ", " + std::to_string(journal->events()) + " journal events in " +
                    std::to_string(complete) + " batches, " + std::to_string(journal->inputsNotTaken()) +
                    " logged inputs the node did not take";
    if (!journal->endReason().empty()) {
      replayed_part += "; compared up to log time " +
                       secondsText(journal->completeUntilUtime() - first_utime) +
                       " s: " + journal->endReason();
    }
  } else {
    feed.finish();
    collect();
    inputs_delivered = feed.inputsDelivered();
  }
  if (inputs_delivered == 0) {
    return fail(kBadInputExitCode, "'" + options.log + "' holds none of the " + options.node + "'s inputs (" +
                                       channelList(node->inputChannels()) + ")");
  }
  if (recorded.empty()) {
    return fail(kBadInputExitCode, "'" + options.log + "' holds none of the " + options.node +
                                       "'s outputs (" + channelList(outputs) + ") to compare with");
  }

  std::printf(
      "ifar replay-test: %s on %s: %lld inputs replayed from %s s, timers from %s%s; settings from %s\n",
      options.node.c_str(), options.log.c_str(), static_cast<long long>(inputs_delivered),
      secondsText(start_utime - first_utime).c_str(), start_reason.c_str(), replayed_part.c_str(),
      settings_origin.c_str());
  ifar::replay_test::ComparisonSettings settings;
  settings.tolerance = options.tolerance;
  settings.ignored = kWallClockMembers;
  const ifar::echo::MessageTypes types(ifar::lcmtypes::messageSchema());
  std::optional<std::pair<std::string, ChannelOutcome>> first;
  for (const std::string& channel : outputs) {
    if (recorded.count(channel) == 0 && channel == request.planner_node.channels.dv_graph) {
      std::printf("  %-16s not in the log (ifar run does not publish it): not compared\n", channel.c_str());
      continue;
    }
    const ChannelOutcome outcome = compareChannel(types, recorded[channel], replayed[channel], settings);
    std::printf("  %-16s %6zu recorded %6zu replayed  %s\n", channel.c_str(), outcome.recorded,
                outcome.replayed,
                outcome.first_difference
                    ? ("differ from message " + std::to_string(*outcome.first_difference)).c_str()
                    : "same");
    if (outcome.first_difference && (!first || outcome.log_time_us < first->second.log_time_us)) {
      first = std::make_pair(channel, outcome);
    }
  }
  const std::string compared =
      options.tolerance > 0.0 ? "reals within " + std::to_string(options.tolerance) : "exact";
  if (!first) {
    std::printf(
        "same: every output of the %s matches the log (%s; the planner's stage timings, wall-clock, not "
        "compared)\n",
        options.node.c_str(), compared.c_str());
    return 0;
  }
  const ChannelOutcome& outcome = first->second;
  std::printf("different: %s message %zu of %zu (log time %s s): %s\n", first->first.c_str(),
              *outcome.first_difference, outcome.recorded, secondsText(outcome.log_time_us).c_str(),
              outcome.difference.c_str());
  if (options.node == "planner") {
    const std::string note = budgetNote(
        request.planner, recorded[request.planner_node.channels.planner_status], outcome.log_time_us);
    if (!note.empty()) {
      std::printf("note: %s\n", note.c_str());
    }
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Replays a log's inputs into one node's core (planner or executive) on the log's own clock and "
      "compares "
      "its outputs with the ones recorded, message by message and member by member: exact, or reals within "
      "--tolerance; the planner's stage timings (wall clock) are not compared. Prints the first difference.\n"
      "Exit code 0 when they agree, 1 when they differ, 2 on bad input."};
  Options options;
  app.add_option("log", options.log, "LCM log (of ifar run --log, or of ifar record)")->required();
  app.add_option("--node", options.node, "the node to replay")
      ->required()
      ->check(CLI::IsMember({"planner", "executive"}));
  app.add_option("--config-dir", options.config_dir,
                 "directory with the config files the node ran with (as ifar run --config-dir)")
      ->capture_default_str();
  app.add_option(
      "--set", options.sets,
      "KEY=VALUE: a key of the node's configuration replaced, checked like the file's own (repeatable); e.g. "
      "--set interaction.enabled=false for a log of ifar run --no-interaction");
  app.add_flag(
      "--node-config-from-dir", options.node_config_from_dir,
      "the node's own file (planner.yaml or executive.yaml) from --config-dir even when the log holds "
      "the daemon's journal, whose first batch states the configuration it ran with");
  app.add_option("--tolerance", options.tolerance,
                 "largest difference of a real member that counts as the same")
      ->check(ifar::common::atLeast(0.0))
      ->capture_default_str();
  app.add_option(
      "--start-utime", options.start_utime,
      "when the node started, microseconds since the epoch: its timers run a period after it (default: "
      "the runner's clock origin for a log of ifar run, else the log's first event)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  return run(options);
}
