#include "tools/replay/replay_filter.hpp"

#include <array>
#include <stdexcept>
#include <utility>

#include "common/byte_order.hpp"
#include "ifar/can_frame_t.hpp"
#include "ifar/e_stop_t.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "lcmtypes/checked_decode.hpp"

namespace ifar::replay {
namespace {

constexpr std::array<const char*, 3> kCommandChannels = {"VELOCITY_CMD", "E_STOP", "GOAL"};

// CANopen function codes (CiA 301) of what a drive acts on; the node id is the low 7 bits.
constexpr std::int32_t kNmt = 0x000;
constexpr std::int32_t kSync = 0x080;
constexpr std::int32_t kTime = 0x100;
constexpr std::array<std::int32_t, 5> kReceivedByNode = {0x200, 0x300, 0x400, 0x500, 0x600};  // RPDO1-4, SDO
// ifar-motor-driver is node 127 (motor.master_node_id): the drives' heartbeat consumer watches 0x77F.
constexpr std::int32_t kMotorDriverHeartbeat = 0x77F;
constexpr std::uint32_t kStandardIdMask = 0x7FF;

std::optional<std::regex> compile(const std::string& pattern, const char* option)
{
  if (pattern.empty()) {
    return std::nullopt;
  }
  try {
    return std::regex(pattern, std::regex::ECMAScript);
  } catch (const std::regex_error& error) {
    throw std::invalid_argument(std::string(option) + " '" + pattern +
                                "' is not a regular expression: " + error.what());
  }
}

std::int64_t fingerprintOf(common::ByteView data)
{
  return data.size() >= 8 ? static_cast<std::int64_t>(common::readUint64Be(data.data())) : 0;
}

bool isCommandType(std::int64_t fingerprint)
{
  return fingerprint == velocity_cmd_t::getHash() || fingerprint == e_stop_t::getHash() ||
         fingerprint == goal_t::getHash();
}

}  // namespace

bool isDriveCommandFrame(std::int32_t id, std::int8_t flags)
{
  const auto not_data = static_cast<std::int8_t>(can_frame_t::FLAG_EXTENDED | can_frame_t::FLAG_REMOTE |
                                                 can_frame_t::FLAG_ERROR);
  if ((flags & not_data) != 0 || (static_cast<std::uint32_t>(id) & ~kStandardIdMask) != 0U) {
    return false;
  }
  if (id == kNmt || id == kSync || id == kTime || id == kMotorDriverHeartbeat) {
    return true;
  }
  const std::int32_t node = id & 0x7F;
  const std::int32_t function = id & 0x780;
  for (const std::int32_t code : kReceivedByNode) {
    if (function == code && node != 0) {
      return true;
    }
  }
  return false;
}

ReplayFilter::ReplayFilter(const std::string& include, const std::string& exclude,
                           std::set<std::string> allowed_commands)
    : include_(compile(include, "--channels")),
      exclude_(compile(exclude, "--exclude")),
      allowed_commands_(std::move(allowed_commands))
{
}

Verdict ReplayFilter::classify(const std::string& channel, common::ByteView data) const
{
  if ((include_ && !std::regex_match(channel, *include_)) ||
      (exclude_ && std::regex_match(channel, *exclude_))) {
    return Verdict::kNotSelected;
  }
  if (allowed_commands_.count(channel) != 0) {
    return Verdict::kPublish;
  }
  bool command_channel = false;
  for (const char* name : kCommandChannels) {
    command_channel = command_channel || channel == name;
  }
  const std::int64_t fingerprint = fingerprintOf(data);
  if (command_channel || isCommandType(fingerprint)) {
    return Verdict::kCommand;
  }
  if (fingerprint == can_frame_t::getHash()) {
    can_frame_t frame;
    // A frame that does not decode cannot be shown not to be a command: left out with them.
    if (!lcmtypes::decodeLcm(frame, data.data(), data.size()).ok() ||
        isDriveCommandFrame(frame.id, frame.flags)) {
      return Verdict::kDriveCommand;
    }
  }
  return Verdict::kPublish;
}

std::string ReplayFilter::description() const
{
  std::string text =
      "leaving out commands: the channels VELOCITY_CMD, E_STOP and GOAL, velocity_cmd_t, e_stop_t and goal_t "
      "on any channel, and CAN frames the drives act on (NMT, SYNC, TIME, RPDO1-4, SDO requests, "
      "ifar-motor-driver's heartbeat 0x77F) in can_frame_t on any channel";
  if (allowed_commands_.empty()) {
    return text + " (--allow-command CHANNEL publishes one channel's)";
  }
  text += ", except on";
  for (const auto& channel : allowed_commands_) {
    text += " " + channel;
  }
  return text + " (--allow-command)";
}

}  // namespace ifar::replay
