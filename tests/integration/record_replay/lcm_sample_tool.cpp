// Test tool for the record/replay integration test: publishes one sample of every project type on the
// bus, checks a log file holds exactly those, or waits on the bus until each has arrived intact (the
// recorder's own heartbeats, recorded with them, are left aside).
//
//   lcm_sample_tool publish            publish every sample once (LCM_DEFAULT_URL or LCM's default)
//   lcm_sample_tool check-log FILE     every sample is in FILE once, byte for byte
//   lcm_sample_tool expect SECONDS     exit 0 once every sample arrived and decoded to the values sent

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "ifar/heartbeat_t.hpp"
#include "lcmtypes/checked_decode.hpp"
#include "lcmtypes/samples/sample_messages.hpp"

namespace {

using ifar::lcmtypes_samples::allSampleMessages;
using ifar::lcmtypes_samples::SampleMessage;

std::map<std::string, SampleMessage> samplesByChannel()
{
  std::map<std::string, SampleMessage> result;
  for (auto& sample : allSampleMessages()) {
    result.emplace(sample.channel, std::move(sample));
  }
  return result;
}

// `ifar record` publishes its own heartbeat on HEARTBEAT, and records it: not one of the samples.
bool isRecorderHeartbeat(const std::string& channel, const void* data, std::size_t size)
{
  ifar::heartbeat_t beat;
  return channel == "HEARTBEAT" && ifar::lcmtypes::decodeLcm(beat, data, size).ok() &&
         beat.process == "recorder";
}

// What arrived on one channel compared with what was sent; "" when equal.
std::string compare(const SampleMessage& sample, const std::uint8_t* data, std::size_t size)
{
  std::vector<std::uint8_t> reencoded;
  if (!sample.reencode(ifar::common::ByteView(data, size), reencoded)) {
    return "does not decode as " + sample.type_name;
  }
  return reencoded == sample.encoded ? "" : "decodes to values other than those sent";
}

int publish()
{
  lcm::LCM bus;
  if (!bus.good()) {
    std::fprintf(stderr, "cannot start LCM\n");
    return 1;
  }
  for (const auto& sample : allSampleMessages()) {
    bus.publish(sample.channel, sample.encoded.data(), static_cast<unsigned>(sample.encoded.size()));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::printf("published %zu messages\n", allSampleMessages().size());
  return 0;
}

int checkLog(const std::string& path)
{
  lcm::LogFile log(path, "r");
  if (!log.good()) {
    std::fprintf(stderr, "cannot open log %s\n", path.c_str());
    return 1;
  }
  const auto samples = samplesByChannel();
  std::map<std::string, int> seen;
  int failures = 0;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    const auto found = samples.find(event->channel);
    if (found == samples.end() || isRecorderHeartbeat(event->channel, event->data, event->datalen)) {
      continue;
    }
    ++seen[event->channel];
    const std::string problem = compare(found->second, static_cast<const std::uint8_t*>(event->data),
                                        static_cast<std::size_t>(event->datalen));
    if (!problem.empty()) {
      std::fprintf(stderr, "log: %s %s\n", event->channel.c_str(), problem.c_str());
      ++failures;
    }
  }
  for (const auto& [channel, sample] : samples) {
    if (seen[channel] != 1) {
      std::fprintf(stderr, "log: %s (%s) recorded %d times, expected once\n", channel.c_str(),
                   sample.type_name.c_str(), seen[channel]);
      ++failures;
    }
  }
  std::printf("log %s: %zu channels checked, %d problems\n", path.c_str(), samples.size(), failures);
  return failures == 0 ? 0 : 1;
}

class Expectation {
 public:
  explicit Expectation(std::map<std::string, SampleMessage> samples) : samples_(std::move(samples)) {}
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel)
  {
    const auto found = samples_.find(channel);
    if (found == samples_.end() || isRecorderHeartbeat(channel, buffer->data, buffer->data_size)) {
      return;
    }
    const std::string problem =
        compare(found->second, static_cast<const std::uint8_t*>(buffer->data), buffer->data_size);
    if (problem.empty()) {
      arrived_.insert(channel);
    } else {
      std::fprintf(stderr, "bus: %s %s\n", channel.c_str(), problem.c_str());
      ++failures_;
    }
  }
  bool complete() const { return arrived_.size() == samples_.size(); }
  int failures() const { return failures_; }
  void reportMissing() const
  {
    for (const auto& [channel, sample] : samples_) {
      if (arrived_.count(channel) == 0) {
        std::fprintf(stderr, "bus: %s (%s) never arrived\n", channel.c_str(), sample.type_name.c_str());
      }
    }
  }

 private:
  std::map<std::string, SampleMessage> samples_;
  std::set<std::string> arrived_;
  int failures_ = 0;
};

int expect(double seconds)
{
  lcm::LCM bus;
  if (!bus.good()) {
    std::fprintf(stderr, "cannot start LCM\n");
    return 1;
  }
  Expectation expectation(samplesByChannel());
  bus.subscribe(".*", &Expectation::onMessage, &expectation);
  std::printf("listening\n");
  std::fflush(stdout);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!expectation.complete() && std::chrono::steady_clock::now() < deadline) {
    bus.handleTimeout(100);
  }
  if (!expectation.complete()) {
    expectation.reportMissing();
    return 1;
  }
  std::printf("all messages arrived with the values sent (%d problems)\n", expectation.failures());
  return expectation.failures() == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv)
{
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "publish") {
    return publish();
  }
  if (mode == "check-log" && argc > 2) {
    return checkLog(argv[2]);
  }
  if (mode == "expect" && argc > 2) {
    return expect(std::atof(argv[2]));
  }
  std::fprintf(stderr, "usage: lcm_sample_tool publish | check-log FILE | expect SECONDS\n");
  return 2;
}
