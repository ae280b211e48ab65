#include "tools/view/view_feed.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <set>
#include <variant>

#include "common/json_text.hpp"
#include "tools/echo/message_format.hpp"

namespace ifar::view {
namespace {

using echo::Members;
using echo::Value;

// Raw sensor streams: hundreds a second, nothing a page draws. Counted, never forwarded.
const std::set<std::string> kRawTypes = {"velodyne_packet_t", "can_frame_t"};
// Events and states a page must not miss one of: never thinned.
const std::set<std::string> kEveryMessageTypes = {"heartbeat_t",       "affordance_t",    "goal_t",
                                                  "blocked_passage_t", "e_stop_t",        "exec_status_t",
                                                  "dv_graph_t",        "planner_status_t"};
// The rate shown per channel is counted over this window.
constexpr std::int64_t kRateWindowUs = 3'000'000;
// A pose this much older than the last one means the clock went back: a replay started again.
constexpr std::int64_t kTimeJumpBackUs = 1'000'000;

const Value* member(const Members& members, const std::string& name)
{
  for (const auto& [member_name, value] : members) {
    if (member_name == name) {
      return &value;
    }
  }
  return nullptr;
}

double realAt(const Value* list, std::size_t index)
{
  if (list == nullptr || list->kind != Value::Kind::kList || index >= list->elements.size()) {
    return std::nan("");
  }
  return list->elements[index].real;
}

std::string numberText(double value)
{
  if (!std::isfinite(value)) {
    return "null";
  }
  std::array<char, 40> text{};
  const auto result = std::to_chars(text.begin(), text.end(), value);
  return std::string(text.data(), result.ptr);
}

}  // namespace

ViewFeed::ViewFeed(const lcm_wire::Schema& schema, FeedSettings settings)
    : types_(schema), settings_(settings)
{
}

ViewFeed::Channel& ViewFeed::channelNamed(const std::string& name)
{
  Channel& channel = channels_[name];
  channel.statistics.channel = name;
  return channel;
}

FeedUpdate ViewFeed::onMessage(const std::string& channel_name, common::ByteView bytes,
                               std::int64_t receive_utime)
{
  FeedUpdate update;
  if (channel_name == "LCM_SELF_TEST") {
    return update;  // LCM's own udpm loopback probe
  }
  Channel& channel = channelNamed(channel_name);
  ChannelStatistics& statistics = channel.statistics;
  ++statistics.messages;
  statistics.bytes += static_cast<std::int64_t>(bytes.size());
  channel.recent_utimes.push_back(receive_utime);
  const auto window_start = std::lower_bound(channel.recent_utimes.begin(), channel.recent_utimes.end(),
                                             receive_utime - kRateWindowUs);
  channel.recent_utimes.erase(channel.recent_utimes.begin(), window_start);

  const lcm_wire::StructType* type = types_.typeOf(bytes);
  if (type == nullptr) {
    ++statistics.undecodable;
    return update;
  }
  statistics.type_name = type->name;
  if (kRawTypes.count(type->name) > 0) {
    return update;
  }
  std::variant<Members, std::string> decoded = types_.decode(*type, bytes);
  if (std::holds_alternative<std::string>(decoded)) {
    ++statistics.undecodable;
    return update;
  }
  const Members& members = std::get<Members>(decoded);
  if (type->name == "pose_t") {
    noticeTimeJump(bytes, update);
    const Value* position = member(members, "position");
    const double x = realAt(position, 0);
    const double y = realAt(position, 1);
    if (std::isfinite(x) && std::isfinite(y)) {
      const bool far_enough =
          trajectory_.empty() ||
          std::hypot(x - trajectory_.back().x, y - trajectory_.back().y) >= settings_.trajectory_spacing_m;
      if (far_enough) {
        trajectory_.push_back({x, y});
        if (trajectory_.size() >= settings_.max_trajectory_points) {
          std::vector<TrajectoryPoint> thinned;
          thinned.reserve(trajectory_.size() / 2 + 1);
          for (std::size_t index = 0; index < trajectory_.size(); index += 2) {
            thinned.push_back(trajectory_[index]);
          }
          thinned.push_back(trajectory_.back());
          trajectory_ = std::move(thinned);
        }
      }
    }
  }

  Publication publication;
  publication.channel = channel_name;
  publication.type_name = type->name;
  publication.receive_utime = receive_utime;
  publication.message_json = echo::jsonObject(members);
  publication.page_line = echo::jsonLine({channel_name, type->name, receive_utime}, members);
  remember(channel, publication, members);

  const double interval_us = settings_.max_rate_hz > 0.0 ? 1e6 / settings_.max_rate_hz : 0.0;
  const bool every_message = kEveryMessageTypes.count(type->name) > 0;
  if (every_message || !channel.sent_any ||
      static_cast<double>(receive_utime - channel.last_sent_utime) >= interval_us) {
    channel.sent_any = true;
    channel.last_sent_utime = receive_utime;
    channel.held.reset();
    ++statistics.forwarded;
    update.publication = std::move(publication);
  } else {
    channel.held = std::move(publication);
  }
  return update;
}

void ViewFeed::noticeTimeJump(common::ByteView bytes, FeedUpdate& update)
{
  // pose_t starts with its fingerprint (8 bytes) and utime (int64, big-endian).
  if (bytes.size() < 16) {
    return;
  }
  std::uint64_t bits = 0;
  for (std::size_t index = 8; index < 16; ++index) {
    bits = (bits << 8U) | bytes[index];
  }
  const auto utime = static_cast<std::int64_t>(bits);
  if (last_pose_utime_ != 0 && utime < last_pose_utime_ - kTimeJumpBackUs) {
    trajectory_.clear();
    first_pose_utime_ = 0;
    // What the old timeline left is not the new one's: a late page must not see a graph from its future.
    for (auto& [name, channel] : channels_) {
      channel.held.reset();
      if (channel.statistics.type_name != "heartbeat_t") {
        channel.latest.clear();
      }
    }
    update.reset = "the pose time went back " +
                   numberText(static_cast<double>(last_pose_utime_ - utime) * 1e-6) +
                   " s (a replay or simulator started again)";
  }
  last_pose_utime_ = utime;
  if (first_pose_utime_ == 0) {
    first_pose_utime_ = utime;
  }
}

void ViewFeed::remember(Channel& channel, const Publication& publication, const Members& members)
{
  std::string key;
  if (publication.type_name == "heartbeat_t") {
    if (const Value* process = member(members, "process"); process != nullptr) {
      key = process->text;
    }
  }
  channel.latest[key] = publication;
}

std::vector<Publication> ViewFeed::due(std::int64_t now_utime)
{
  const double interval_us = settings_.max_rate_hz > 0.0 ? 1e6 / settings_.max_rate_hz : 0.0;
  std::vector<Publication> ready;
  for (auto& [name, channel] : channels_) {
    if (channel.held && static_cast<double>(now_utime - channel.last_sent_utime) >= interval_us) {
      channel.last_sent_utime = now_utime;
      ++channel.statistics.forwarded;
      ready.push_back(std::move(*channel.held));
      channel.held.reset();
    }
  }
  std::sort(ready.begin(), ready.end(), [](const Publication& first, const Publication& second) {
    return first.receive_utime < second.receive_utime;
  });
  return ready;
}

std::vector<Publication> ViewFeed::latest() const
{
  std::vector<Publication> publications;
  for (const auto& [name, channel] : channels_) {
    std::vector<Publication> newest = latestOf(name);
    publications.insert(publications.end(), newest.begin(), newest.end());
  }
  return publications;
}

std::vector<Publication> ViewFeed::latestOf(const std::string& channel) const
{
  std::vector<Publication> publications;
  if (const auto found = channels_.find(channel); found != channels_.end()) {
    for (const auto& [key, publication] : found->second.latest) {
      publications.push_back(publication);
    }
  }
  return publications;
}

std::vector<ChannelStatistics> ViewFeed::statistics(std::int64_t now_utime) const
{
  std::vector<ChannelStatistics> all;
  for (const auto& [name, channel] : channels_) {
    ChannelStatistics statistics = channel.statistics;
    const auto recent =
        std::count_if(channel.recent_utimes.begin(), channel.recent_utimes.end(),
                      [now_utime](std::int64_t utime) { return utime > now_utime - kRateWindowUs; });
    statistics.rate_hz = static_cast<double>(recent) / (static_cast<double>(kRateWindowUs) * 1e-6);
    all.push_back(statistics);
  }
  return all;
}

std::string ViewFeed::trajectoryLine() const
{
  std::string text =
      "{\"view\":\"trajectory\",\"first_utime\":" + std::to_string(first_pose_utime_) + ",\"points\":[";
  for (std::size_t index = 0; index < trajectory_.size(); ++index) {
    text += (index == 0 ? "[" : ",[") + numberText(trajectory_[index].x) + "," +
            numberText(trajectory_[index].y) + "]";
  }
  return text + "]}";
}

std::string ViewFeed::statisticsLine(std::int64_t now_utime) const
{
  std::string text = "{\"view\":\"channels\",\"now_utime\":" + std::to_string(now_utime) + ",\"channels\":[";
  bool first = true;
  for (const ChannelStatistics& statistics : statistics(now_utime)) {
    text += std::string(first ? "" : ",") + "{\"channel\":" + common::jsonString(statistics.channel) +
            ",\"type\":" + common::jsonString(statistics.type_name) +
            ",\"messages\":" + std::to_string(statistics.messages) +
            ",\"forwarded\":" + std::to_string(statistics.forwarded) +
            ",\"undecodable\":" + std::to_string(statistics.undecodable) +
            ",\"bytes\":" + std::to_string(statistics.bytes) +
            ",\"rate_hz\":" + numberText(statistics.rate_hz) + "}";
    first = false;
  }
  return text + "]}";
}

}  // namespace ifar::view
