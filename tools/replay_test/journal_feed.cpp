#include "tools/replay_test/journal_feed.hpp"

#include <algorithm>
#include <utility>

#include "bus/node_journal/input_hash.hpp"
#include "common/lcm_log/strict_event_reader.hpp"
#include "lcmtypes/checked_decode.hpp"

namespace ifar::replay_test {
namespace {

// Logged inputs wait here until the journal names them; the journal lags its inputs by a batch (0.25 s),
// so a channel this far ahead holds messages the node never took (counted, dropped oldest first).
constexpr std::size_t kMaxWaitingInputs = 1U << 16U;

std::optional<node_journal_t> decodeBatch(const lcm_log::LogEvent& event)
{
  node_journal_t batch{};  // decoded in full below; zeroed so no path copies an unset member
  if (!lcmtypes::decodeLcm(batch, event.data.data(), event.data.size()).ok()) {
    return std::nullopt;
  }
  if (batch.kinds.size() != batch.codes.size() || batch.kinds.size() != batch.utimes.size() ||
      batch.kinds.size() != batch.hashes.size()) {
    return std::nullopt;
  }
  return batch;
}

std::string seconds(std::int64_t microseconds)
{
  return std::to_string(static_cast<double>(microseconds) * 1e-6);
}

}  // namespace

std::optional<node_journal_t> firstJournalBatch(const std::string& path, const std::string& channel)
{
  lcm_log::LogReader log = lcm_log::LogReader::open(path);
  if (!log.openError().empty()) {
    return std::nullopt;
  }
  lcm_log::StrictEventReader events(log);
  lcm_log::LogEvent event;
  while (events.next(event)) {
    if (event.channel == channel) {
      return decodeBatch(event);
    }
  }
  return std::nullopt;
}

JournalFeed::JournalFeed(std::string journal_channel, const node_journal_t& first,
                         std::set<std::string> inputs, JournalHooks hooks)
    : journal_channel_(std::move(journal_channel)),
      pid_(first.pid),
      start_utime_(first.start_utime),
      inputs_(std::move(inputs)),
      hooks_(std::move(hooks))
{
}

void JournalFeed::add(const lcm_log::LogEvent& event)
{
  if (!end_reason_.empty()) {
    return;
  }
  if (event.channel == journal_channel_) {
    takeBatch(event);
  } else if (inputs_.count(event.channel) > 0) {
    std::deque<LoggedInput>& waiting = logged_inputs_[event.channel];
    waiting.push_back(
        {node_journal::inputHash(common::ByteView(event.data.data(), event.data.size())), event.data});
    if (waiting.size() > kMaxWaitingInputs) {
      waiting.pop_front();
      ++inputs_not_taken_;
    }
  }
  replayPending();
}

void JournalFeed::takeBatch(const lcm_log::LogEvent& event)
{
  const std::optional<node_journal_t> batch = decodeBatch(event);
  const std::string at = " at log event " + std::to_string(event.event_number);
  if (!batch) {
    end("a journal batch that does not decode" + at);
    return;
  }
  if (batch->pid != pid_ || batch->start_utime != start_utime_) {
    end("the node restarted" + at + " (pid " + std::to_string(batch->pid) + ")");
    return;
  }
  if (batch->first_event != next_event_) {
    end("journal events " + std::to_string(next_event_) + " to " + std::to_string(batch->first_event - 1) +
        " are not in the log" + at);
    return;
  }
  for (std::size_t index = 0; index < batch->kinds.size(); ++index) {
    PendingEvent pending;
    pending.batch = batches_logged_;
    pending.batch_log_utime = event.timestamp_us;
    pending.kind = batch->kinds[index];
    pending.code = batch->codes[index];
    pending.utime = batch->utimes[index];
    pending.hash = batch->hashes[index];
    if (pending.kind == node_journal_t::KIND_INPUT) {
      if (pending.code < 0 || static_cast<std::size_t>(pending.code) >= batch->channels.size()) {
        end("a journal input names channel " + std::to_string(pending.code) + " of " +
            std::to_string(batch->channels.size()) + at);
        return;
      }
      pending.channel = batch->channels[static_cast<std::size_t>(pending.code)];
      if (inputs_.count(pending.channel) == 0) {
        end("the journal names input channel " + pending.channel + ", not one of this node's" + at);
        return;
      }
    }
    pending_.push_back(std::move(pending));
  }
  next_event_ += static_cast<std::int64_t>(batch->kinds.size());
  ++batches_logged_;
}

void JournalFeed::replayPending()
{
  while (!pending_.empty() && end_reason_.empty()) {
    const PendingEvent& event = pending_.front();
    current_batch_ = event.batch;
    if (event.kind == node_journal_t::KIND_INPUT) {
      std::deque<LoggedInput>& waiting = logged_inputs_[event.channel];
      const auto found = std::find_if(waiting.begin(), waiting.end(), [&event](const LoggedInput& input) {
        return input.hash == event.hash;
      });
      if (found == waiting.end()) {
        return;  // not logged yet
      }
      inputs_not_taken_ += found - waiting.begin();
      const LoggedInput input = std::move(*found);
      waiting.erase(waiting.begin(), found + 1);
      ++inputs_delivered_;
      hooks_.deliver(event.channel, common::ByteView(input.bytes.data(), input.bytes.size()), event.utime);
    } else {
      hooks_.event(event.kind, event.code, event.utime);
    }
    ++events_replayed_;
    const std::int64_t batch = event.batch;
    const std::int64_t batch_log_utime = event.batch_log_utime;
    pending_.pop_front();
    if (pending_.empty() || pending_.front().batch != batch) {
      complete_batches_ = batch + 1;
      complete_until_utime_ = batch_log_utime;
    }
  }
}

void JournalFeed::finish()
{
  replayPending();
  if (!pending_.empty() && end_reason_.empty()) {
    const PendingEvent& event = pending_.front();
    end("the node took a " + event.channel + " message (its time " + seconds(event.utime - start_utime_) +
        " s after its start) that is not in the log");
  }
}

void JournalFeed::end(std::string reason)
{
  end_reason_ = std::move(reason);
  pending_.clear();
}

}  // namespace ifar::replay_test
