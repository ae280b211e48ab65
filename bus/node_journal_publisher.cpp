#include "bus/node_journal_publisher.hpp"

#include <unistd.h>

#include <optional>
#include <utility>

namespace ifar::bus {
namespace {

// A batch holds a quarter second of inputs (about 250 packets and poses: a few kB), so a log cut short
// loses little of the journal and a replay waits little for it.
constexpr double kBatchPeriodS = 0.25;

}  // namespace

NodeJournalPublisher::NodeJournalPublisher(RunLoop& loop, std::string channel, std::string node,
                                           std::int64_t start_utime, std::set<std::string> inputs,
                                           std::function<void()> before_input)
    : loop_(loop), channel_(std::move(channel)), recorder_(std::move(node), start_utime, getpid())
{
  loop_.observeInputs([this, inputs = std::move(inputs), before_input = std::move(before_input)](
                          const std::string& input_channel, common::ByteView bytes, std::int64_t utime) {
    if (inputs.count(input_channel) == 0) {
      return;
    }
    if (before_input) {
      before_input();
    }
    recorder_.input(input_channel, bytes, utime);
  });
  loop_.every(kBatchPeriodS, [this] { flush(); });
}

NodeJournalPublisher::~NodeJournalPublisher()
{
  loop_.observeInputs({});
  flush();
}

void NodeJournalPublisher::flush()
{
  if (const std::optional<node_journal_t> batch = recorder_.takeBatch(loop_.now())) {
    loop_.publish(channel_, *batch);
  }
}

}  // namespace ifar::bus
