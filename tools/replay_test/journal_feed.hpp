#pragma once
// A log of the daemons fed to a node as the daemon's own loop fed it: its journal (node_journal_t, on the
// node's journal channel) names each input it took (channel and hash of the bytes; the message itself is
// found among the logged ones), each timer with the clock it read and each finished planner job with its
// stamp. Events go to the hooks in the journal's order, each input once its bytes are in the log.
// The journal comes in batches; outputs stand in the log between the batches of the events that made
// them (one process, one socket), so a replay compares batch by batch: batch() tags what the node
// publishes, batchesLogged() what the log recorded, and the first completeBatches() batches are comparable.
// A restarted node, a lost batch or an input the log lacks ends the replayable part (endReason says why).

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/lcm_log/log_reader.hpp"
#include "common/span.hpp"
#include "ifar/node_journal_t.hpp"

namespace ifar::replay_test {

struct JournalHooks {
  std::function<void(const std::string& channel, common::ByteView bytes, std::int64_t utime)> deliver;
  /// A timer (node_journal_t::KIND_TIMER with its code), a finished job (its stamp) or the stop.
  std::function<void(std::int8_t kind, std::int16_t code, std::int64_t utime)> event;
};

/// The first batch of `node`'s journal on `channel` in the log at `path`, if any (read up to it).
std::optional<node_journal_t> firstJournalBatch(const std::string& path, const std::string& channel);

class JournalFeed {
 public:
  /// `first`: the journal's first batch as firstJournalBatch found it; `inputs`: the node's input channels.
  JournalFeed(std::string journal_channel, const node_journal_t& first, std::set<std::string> inputs,
              JournalHooks hooks);

  /// The next event of the log, in log order.
  void add(const lcm_log::LogEvent& event);
  /// The log has ended: an input the journal names and the log lacks ends the replayable part here.
  void finish();

  /// The batch whose events are being replayed (tags what the node publishes now).
  std::int64_t batch() const { return current_batch_; }
  /// Journal batches logged so far (tags a recorded output: it came of that batch's events).
  std::int64_t batchesLogged() const { return batches_logged_; }
  /// Batches replayed whole.
  std::int64_t completeBatches() const { return complete_batches_; }
  /// Why the replay stopped before the log's end; empty when it replayed the whole journal.
  const std::string& endReason() const { return end_reason_; }
  /// Log time (utime) of the last complete batch.
  std::int64_t completeUntilUtime() const { return complete_until_utime_; }

  std::int64_t inputsDelivered() const { return inputs_delivered_; }
  /// Logged inputs the node did not take (it had not received them, or they did not decode).
  std::int64_t inputsNotTaken() const { return inputs_not_taken_; }
  std::int64_t events() const { return events_replayed_; }

 private:
  struct PendingEvent {
    std::int64_t batch = 0;
    std::int64_t batch_log_utime = 0;
    std::int8_t kind = 0;
    std::int16_t code = 0;
    std::int64_t utime = 0;
    std::int32_t hash = 0;
    std::string channel;  // inputs
  };
  struct LoggedInput {
    std::int32_t hash = 0;
    std::vector<std::uint8_t> bytes;
  };
  void takeBatch(const lcm_log::LogEvent& event);
  void replayPending();
  void end(std::string reason);

  std::string journal_channel_;
  std::int32_t pid_;
  std::int64_t start_utime_;
  std::set<std::string> inputs_;
  JournalHooks hooks_;
  std::deque<PendingEvent> pending_;
  std::map<std::string, std::deque<LoggedInput>> logged_inputs_;
  std::int64_t next_event_ = 0;  // the journal's event number expected next
  std::int64_t batches_logged_ = 0;
  std::int64_t current_batch_ = 0;
  std::int64_t complete_batches_ = 0;
  std::int64_t complete_until_utime_ = 0;
  std::int64_t inputs_delivered_ = 0;
  std::int64_t inputs_not_taken_ = 0;
  std::int64_t events_replayed_ = 0;
  std::string end_reason_;
};

}  // namespace ifar::replay_test
