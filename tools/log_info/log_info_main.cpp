// ifar log-info LOG: what an LCM log holds, per channel: message count, rate, time span, bytes, and the
// project type recognised from each message's fingerprint (the first 8 bytes of an LCM message). With
// --check every message is decoded as its type and re-encoded to the same bytes; any message that does
// not (or whose type is unknown) is counted per channel and the exit status is 1; LCM's own LCM_SELF_TEST
// messages are left out of the check.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lcmtypes/samples/sample_messages.hpp"

namespace {

struct ChannelSummary {
  std::int64_t count = 0;
  std::int64_t bytes = 0;
  std::int64_t first_utime = 0;
  std::int64_t last_utime = 0;
  std::string type_name;
  std::int64_t undecodable = 0;  // --check: messages that do not decode, or not to the same bytes
};

std::int64_t fingerprintOf(const lcm::LogEvent& event)
{
  if (event.datalen < 8) {
    return 0;
  }
  const auto* bytes = static_cast<const std::uint8_t*>(event.data);
  std::uint64_t value = 0;
  for (int index = 0; index < 8; ++index) {
    value = (value << 8U) | bytes[index];  // LCM encodes the fingerprint big-endian
  }
  return static_cast<std::int64_t>(value);
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Summarises an LCM log per channel: count, rate, span, bytes and message type"};
  std::string path;
  bool check = false;
  app.add_option("log", path, "the .lcmlog file")->required()->check(CLI::ExistingFile);
  app.add_flag("--check", check,
               "decode every message as its project type; exit 1 if any message does not decode");
  CLI11_PARSE(app, argc, argv);

  lcm::LogFile log(path, "r");
  if (!log.good()) {
    std::fprintf(stderr, "ifar log-info: error: cannot read '%s' as an LCM log\n", path.c_str());
    return 1;
  }
  const std::vector<ifar::lcmtypes_samples::SampleMessage> samples =
      ifar::lcmtypes_samples::allSampleMessages();
  std::map<std::int64_t, const ifar::lcmtypes_samples::SampleMessage*> types;
  for (const auto& sample : samples) {
    types[sample.fingerprint] = &sample;
  }
  std::vector<std::uint8_t> reencoded;
  std::map<std::string, ChannelSummary> channels;
  std::int64_t total = 0;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    auto& summary = channels[event->channel];
    const auto found = types.find(fingerprintOf(*event));
    if (summary.count == 0) {
      summary.first_utime = event->timestamp;
      summary.type_name = found != types.end() ? found->second->type_name : "(not a project type)";
    }
    // LCM_SELF_TEST is LCM's own udpm loopback probe, not a project message.
    if (check && event->channel != "LCM_SELF_TEST") {
      const ifar::common::ByteView bytes(static_cast<const std::uint8_t*>(event->data),
                                         static_cast<std::size_t>(event->datalen));
      const bool decodes = found != types.end() && found->second->reencode(bytes, reencoded) &&
                           reencoded.size() == bytes.size() &&
                           std::equal(reencoded.begin(), reencoded.end(), bytes.begin());
      summary.undecodable += decodes ? 0 : 1;
    }
    ++summary.count;
    summary.bytes += event->datalen;
    summary.last_utime = event->timestamp;
    ++total;
  }
  std::printf("%-20s %-20s %9s %9s %9s %11s\n", "channel", "type", "messages", "rate Hz", "span s", "bytes");
  for (const auto& [channel, summary] : channels) {
    const double span = static_cast<double>(summary.last_utime - summary.first_utime) * 1e-6;
    const double rate = span > 0.0 ? static_cast<double>(summary.count - 1) / span : 0.0;
    std::printf("%-20s %-20s %9lld %9.1f %9.2f %11lld\n", channel.c_str(), summary.type_name.c_str(),
                static_cast<long long>(summary.count), rate, span, static_cast<long long>(summary.bytes));
  }
  std::printf("%lld messages on %zu channels in %s\n", static_cast<long long>(total), channels.size(),
              path.c_str());
  if (!check) {
    return 0;
  }
  std::int64_t failures = 0;
  for (const auto& [channel, summary] : channels) {
    if (summary.undecodable > 0) {
      std::printf("check: %s: %lld of %lld messages do not decode as %s\n", channel.c_str(),
                  static_cast<long long>(summary.undecodable), static_cast<long long>(summary.count),
                  summary.type_name.c_str());
      failures += summary.undecodable;
    }
  }
  std::printf("check: %s\n", failures == 0 ? "every message decodes" : "FAILED");
  return failures == 0 ? 0 : 1;
}
