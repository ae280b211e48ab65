#pragma once
// One node's core driven by a log, as the headless runner drives it: its inputs decoded from the log's
// bytes (checked, as a daemon decodes them) and handed over with their logged receive times, its timers
// on the daemon's periods from the node's start, the planner's jobs run in line at once. What it publishes
// is kept, encoded, with the time it was published, for comparison with what the log holds.
//   planner:   VELODYNE_PACKET, POSE, GOAL, DETECTED_OBJECTS, AFFORDANCE, BLOCKED_PASSAGE in (planner.yaml's
//              channels); GLOBAL_PATH, PLANNER_STATUS (and DV_GRAPH when asked) out; ticks at daemon.rate_hz,
//              the path resent at daemon.path_resend_hz
//   executive: POSE, VELODYNE_PACKET, GLOBAL_PATH, FORCE, MOTOR_STATUS, ODOMETRY, E_STOP in; VELOCITY_CMD,
//              EXEC_STATUS, AFFORDANCE, BLOCKED_PASSAGE out; a control cycle every 20 ms
// A log of the daemons with their journals is driven by the journal instead (ReplayClock::kJournal): the
// timers run when and with the clock the daemon's ran, the planner's jobs finish where its worker's did.

#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "common/span.hpp"
#include "lcmtypes/checked_decode.hpp"
#include "system/scenario_runner.hpp"

namespace ifar::replay_test {

/// One message the node published.
struct Published {
  std::string channel;
  std::vector<std::uint8_t> bytes;
  std::int64_t utime = 0;  // the node's clock when it published
};

class NodeReplay {
 public:
  virtual ~NodeReplay() = default;
  virtual std::set<std::string> inputChannels() const = 0;
  virtual std::set<std::string> outputChannels() const = 0;
  /// An input message received at `receive_utime`; bytes that do not decode are counted and skipped.
  virtual void deliver(const std::string& channel, common::ByteView bytes, std::int64_t receive_utime) = 0;
  /// The timers due at `now_utime` (a log without the node's journal: the runner's schedule).
  virtual void runTimers(std::int64_t now_utime) = 0;
  /// A journaled event of the daemon's loop (journal_feed.hpp): a timer, a finished job, the stop.
  virtual void journalEvent(std::int8_t kind, std::int16_t code, std::int64_t utime) = 0;

  /// What the node published so far, in order; taken out.
  std::vector<Published> takePublished();
  /// Inputs whose bytes did not decode.
  std::int64_t undecodable() const { return undecodable_; }

 protected:
  template <typename Message>
  void publish(const std::string& channel, const Message& message, std::int64_t utime)
  {
    Published published{channel,
                        std::vector<std::uint8_t>(static_cast<std::size_t>(message.getEncodedSize())), utime};
    message.encode(published.bytes.data(), 0, static_cast<int>(published.bytes.size()));
    published_.push_back(std::move(published));
  }
  /// Calls handler(message) when `bytes` decode as Message (checked as a daemon decodes); else counts them.
  template <typename Message, typename Handler>
  void take(common::ByteView bytes, Handler handler)
  {
    Message message;
    if (lcmtypes::decodeLcm(message, bytes.data(), bytes.size()).ok()) {
      handler(message);
    } else {
      ++undecodable_;
    }
  }

 private:
  std::vector<Published> published_;
  std::int64_t undecodable_ = 0;
};

/// How the node's jobs and timers are driven.
enum class ReplayClock {
  kRunner,   // runTimers on the runner's schedule; the planner's jobs finish at once
  kJournal,  // journalEvent only; the planner's jobs finish where the journal says, with its stamp
};

/// The planner node of `request` (its planner settings as the runner lifts them: no wall-clock budgets),
/// started at `start_utime`; `publish_graph`: publish DV_GRAPH as the daemon does (the runner does not).
std::unique_ptr<NodeReplay> plannerReplay(const runner::RunRequest& request, std::int64_t start_utime,
                                          bool publish_graph, ReplayClock clock);

/// The executive node of `request`, started at `start_utime`. Throws std::invalid_argument when the vehicle
/// does not fit the executive.
std::unique_ptr<NodeReplay> executiveReplay(const runner::RunRequest& request, std::int64_t start_utime);

}  // namespace ifar::replay_test
