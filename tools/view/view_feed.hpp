#pragma once
// What the live view forwards from the bus: every message of a project type decoded to JSON (tools/echo),
// the raw sensor streams (Velodyne packets, CAN frames) only counted, fast streams thinned to a rate a
// browser draws, and what a page that joins late needs at once: the latest message of each channel (of each
// process on HEARTBEAT) and the vehicle's trajectory so far. No bus and no sockets: view_main.cpp feeds it
// what LCM delivers and hands what it returns to the web server.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/lcm_wire/schema.hpp"
#include "common/span.hpp"
#include "tools/echo/message_value.hpp"

namespace ifar::view {

struct FeedSettings {
  /// A channel faster than this is thinned to it; the last message of a burst still goes out (trailing).
  double max_rate_hz = 20.0;
  /// The trajectory keeps a pose once the vehicle moved this far from the last one kept, metres.
  double trajectory_spacing_m = 0.05;
  /// At this many points every second one is dropped, so a long run keeps its whole outline.
  std::size_t max_trajectory_points = 20000;
};

/// One message as the view forwards it.
struct Publication {
  std::string channel;
  std::string type_name;
  std::int64_t receive_utime = 0;  // when the view received it, microseconds since the epoch
  std::string message_json;        // the message's members: {"utime":...,...}
  std::string page_line;  // tools/echo's JSON line: {"channel":..,"type":..,"receive_utime":..,"message":..}
};

/// Counts of one channel since the view started.
struct ChannelStatistics {
  std::string channel;
  std::string type_name;         // "" when no message on it was of a project type
  std::int64_t messages = 0;     // received
  std::int64_t forwarded = 0;    // sent on to pages (raw streams: 0)
  std::int64_t undecodable = 0;  // not a project type, or bytes that do not decode
  double rate_hz = 0.0;          // over the last few seconds
  std::int64_t bytes = 0;
};

struct TrajectoryPoint {
  double x = 0.0;
  double y = 0.0;
};

/// What one message from the bus gives.
struct FeedUpdate {
  /// The log's or the simulator's time went back (a replay started again): the trajectory and the newest
  /// messages (heartbeats aside) are dropped, here and on the pages.
  std::optional<std::string> reset;
  /// Sent on now; empty when counted only (raw stream, undecodable) or held back by the rate limit.
  std::optional<Publication> publication;
};

class ViewFeed {
 public:
  /// `schema` must outlive the feed.
  ViewFeed(const lcm_wire::Schema& schema, FeedSettings settings);

  /// One message as LCM delivered it, `receive_utime` on the view's clock.
  FeedUpdate onMessage(const std::string& channel, common::ByteView bytes, std::int64_t receive_utime);
  /// Messages held back by the rate limit whose turn has come at `now_utime`, oldest first.
  std::vector<Publication> due(std::int64_t now_utime);

  /// For a page that joins: the newest message of every forwarded channel (held ones included), one per
  /// process on heartbeat channels, in channel order.
  std::vector<Publication> latest() const;
  /// The newest message of one channel (one per process on a heartbeat channel); none when it has none.
  std::vector<Publication> latestOf(const std::string& channel) const;
  const std::vector<TrajectoryPoint>& trajectory() const { return trajectory_; }
  std::vector<ChannelStatistics> statistics(std::int64_t now_utime) const;

  /// {"view":"trajectory","first_utime":..,"points":[[x,y],...]}: first_utime is the first pose's utime, 0
  /// before any.
  std::string trajectoryLine() const;
  /// {"view":"channels","now_utime":..,"channels":[...]}
  std::string statisticsLine(std::int64_t now_utime) const;

 private:
  struct Channel {
    ChannelStatistics statistics;
    std::vector<std::int64_t> recent_utimes;  // receive times within the rate window
    std::int64_t last_sent_utime = 0;
    bool sent_any = false;
    std::optional<Publication> held;            // thinned out, goes when its turn comes unless replaced
    std::map<std::string, Publication> latest;  // by process on heartbeat channels, else under ""
  };
  Channel& channelNamed(const std::string& name);
  /// A pose stamped well before the last one: the clock went back, the trajectory starts again.
  void noticeTimeJump(common::ByteView bytes, FeedUpdate& update);
  static void remember(Channel& channel, const Publication& publication, const echo::Members& members);

  echo::MessageTypes types_;
  FeedSettings settings_;
  std::map<std::string, Channel> channels_;
  std::vector<TrajectoryPoint> trajectory_;
  std::int64_t last_pose_utime_ = 0;
  std::int64_t first_pose_utime_ = 0;  // of the trajectory: since the start or the last time jump
};

}  // namespace ifar::view
