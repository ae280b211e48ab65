// ifar log-info LOG: what an LCM log holds, per channel: message count, rate, time span, bytes, and the
// project type recognised from each message's fingerprint (the first 8 bytes of an LCM message).

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>

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
  app.add_option("log", path, "the .lcmlog file")->required()->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);

  lcm::LogFile log(path, "r");
  if (!log.good()) {
    std::fprintf(stderr, "ifar log-info: error: cannot read '%s' as an LCM log\n", path.c_str());
    return 1;
  }
  std::map<std::int64_t, std::string> type_names;
  for (const auto& sample : ifar::lcmtypes_samples::allSampleMessages()) {
    type_names[sample.fingerprint] = sample.type_name;
  }
  std::map<std::string, ChannelSummary> channels;
  std::int64_t total = 0;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    auto& summary = channels[event->channel];
    if (summary.count == 0) {
      summary.first_utime = event->timestamp;
      const auto found = type_names.find(fingerprintOf(*event));
      summary.type_name = found != type_names.end() ? found->second : "(not a project type)";
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
  return 0;
}
