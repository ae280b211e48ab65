#pragma once
// What `ifar replay` publishes of a log. A log recorded on a vehicle holds the commands that drove it; played
// onto a live bus they would drive it again. So by default it never publishes a command: the channels
// VELOCITY_CMD, E_STOP and GOAL, any message of their types on another channel, and the CAN frames the
// wheel drives act on (CANopen NMT, SYNC, TIME, RPDO1-4 and SDO requests to any node, and the heartbeat of
// ifar-motor-driver that the drives watch) in can_frame_t on any channel. Each is published only when its
// channel is named with --allow-command. The drives' and sensors' own frames (TPDO, EMCY, SDO answers,
// their heartbeats, the force frame) are observations and are published.

#include <cstdint>
#include <optional>
#include <regex>
#include <set>
#include <string>

#include "common/span.hpp"

namespace ifar::replay {

enum class Verdict : std::uint8_t {
  kPublish,
  kNotSelected,   // left out by --channels / --exclude
  kCommand,       // a command channel or a command type
  kDriveCommand,  // a CAN frame the drives act on
};

/// A CAN frame with this identifier and can_frame_t flags is one a CANopen drive acts on (see above).
/// Extended, remote and error frames are not: the drives use standard data frames only.
bool isDriveCommandFrame(std::int32_t id, std::int8_t flags);

class ReplayFilter {
 public:
  /// `include` and `exclude` are regular expressions (ECMAScript) that must match a whole channel name;
  /// empty: every channel, none. Throws std::invalid_argument naming the option when one does not parse.
  ReplayFilter(const std::string& include, const std::string& exclude,
               std::set<std::string> allowed_commands);

  /// What to do with one event of the log: its channel and its bytes as recorded.
  Verdict classify(const std::string& channel, common::ByteView data) const;

  /// One line for the start of a replay: which commands it leaves out, and which it was allowed.
  std::string description() const;

 private:
  std::optional<std::regex> include_;
  std::optional<std::regex> exclude_;
  std::set<std::string> allowed_commands_;
};

}  // namespace ifar::replay
