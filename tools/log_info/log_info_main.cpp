// ifar log-info LOG: what an LCM log holds, per channel: message count, rate, time span, bytes, and the
// project type recognised from each message's fingerprint (the first 8 bytes of an LCM message). With
// --check every message is decoded as its type and re-encoded to the same bytes; any message that does
// not (or whose type is unknown) is counted per channel and the exit status is 1; LCM's own LCM_SELF_TEST
// messages are left out of the check. A log that is corrupt (bytes that are no event, an event cut short
// or claiming more bytes than the file has) or holds no event at all fails the check too; without
// --check the events that could be read are listed and the corruption is a warning on stderr.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/byte_order.hpp"
#include "common/command_line.hpp"
#include "common/lcm_log/log_reader.hpp"
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

std::int64_t fingerprintOf(const ifar::lcm_log::LogEvent& event)
{
  if (event.data.size() < 8) {
    return 0;
  }
  return static_cast<std::int64_t>(
      ifar::common::readUint64Be(event.data.data()));  // LCM writes it big-endian
}

/// Every problem the reader kept, one a line, each line starting with `prefix`.
void printProblems(std::FILE* stream, const char* prefix, const std::string& path,
                   const ifar::lcm_log::LogReader& log)
{
  std::fprintf(stream, "%s%s is corrupt: %llu problem%s, %llu bytes skipped (not counted above)\n", prefix,
               path.c_str(), static_cast<unsigned long long>(log.problemCount()),
               log.problemCount() == 1 ? "" : "s", static_cast<unsigned long long>(log.skippedBytes()));
  for (const ifar::lcm_log::LogProblem& problem : log.problems()) {
    std::fprintf(stream, "%s  %s\n", prefix, problem.description.c_str());
  }
  if (log.problemCount() > log.problems().size()) {
    std::fprintf(stream, "%s  ... and %llu more\n", prefix,
                 static_cast<unsigned long long>(log.problemCount() - log.problems().size()));
  }
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Summarises an LCM log per channel: count, rate, span, bytes and message type"};
  std::string path;
  bool check = false;
  app.add_option("log", path, "the .lcmlog file")->required()->check(CLI::ExistingFile);
  app.add_flag("--check", check,
               "decode every message as its project type; exit 1 if any message does not decode, the log is "
               "corrupt or it holds no events");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  ifar::lcm_log::LogReader log = ifar::lcm_log::LogReader::open(path);
  if (!log.openError().empty()) {
    std::fprintf(stderr, "ifar log-info: error: cannot read an LCM log: %s\n", log.openError().c_str());
    return ifar::common::kBadInputExitCode;
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
  ifar::lcm_log::LogEvent event;
  while (log.next(event)) {
    auto& summary = channels[event.channel];
    const auto found = types.find(fingerprintOf(event));
    if (summary.count == 0) {
      summary.first_utime = event.timestamp_us;
      summary.type_name = found != types.end() ? found->second->type_name : "(not a project type)";
    }
    // LCM_SELF_TEST is LCM's own udpm loopback probe, not a project message.
    if (check && event.channel != "LCM_SELF_TEST") {
      const ifar::common::ByteView bytes(event.data.data(), event.data.size());
      const bool decodes = found != types.end() && found->second->reencode(bytes, reencoded) &&
                           reencoded.size() == bytes.size() &&
                           std::equal(reencoded.begin(), reencoded.end(), bytes.begin());
      summary.undecodable += decodes ? 0 : 1;
    }
    ++summary.count;
    summary.bytes += static_cast<std::int64_t>(event.data.size());
    summary.last_utime = event.timestamp_us;
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
    if (!log.clean()) {
      printProblems(stderr, "ifar log-info: warning: ", path, log);
    }
    return 0;
  }
  std::int64_t failures = 0;
  if (!log.clean()) {
    printProblems(stdout, "check: ", path, log);
    failures += static_cast<std::int64_t>(log.problemCount());
  }
  if (total == 0) {
    // An empty log is no evidence that anything was recorded: a recorder that never ran leaves one.
    std::printf("check: %s holds no events\n", path.c_str());
    ++failures;
  }
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
