#pragma once
// The Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1, github.com/foxglove/ws-protocol,
// docs/spec.md), so Foxglove or Lichtblick can connect to ifar view: every LCM channel the view forwards is
// one advertised channel (topic = LCM channel, encoding json, schemaName = the LCM type, schema = a JSON
// Schema of echo's JSON for it), a new one advertised to every client when it first carries a message. A
// client subscribes by channel id and from then gets each forwarded message of it, the same thinned stream
// the page gets, as a binary Message Data frame: opcode 0x01, the subscription id (u32 LE), the receive time
// (u64 LE, ns since the epoch) and the message's JSON (echo's "message" object); at once on subscribing, the
// newest one(s) the view holds. What a client sends that is not JSON, not a known op, names an unknown
// channel or subscription, or asks for what is not offered (publishing, parameters, services) is counted and
// answered with a status message. No sockets: what to send whom goes to a Send function. One thread.

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tools/view/view_feed.hpp"
#include "tools/view/web_server.hpp"

namespace YAML {
class Node;
}

namespace ifar::view {

/// The WebSocket path Foxglove clients connect to, and the subprotocol they must ask for there.
constexpr std::string_view kFoxglovePath = "/foxglove";
constexpr std::string_view kFoxgloveSubprotocol = "foxglove.websocket.v1";

struct FoxgloveServerInfo {
  std::string name = "ifar view";
  /// Shown by the client as the server's metadata: the LCM URL, the rate limit.
  std::vector<std::pair<std::string, std::string>> metadata;
};

/// What Foxglove clients asked for and got, since the start.
struct FoxgloveCounts {
  std::int64_t messages_sent = 0;  // Message Data frames, summed over clients
  std::int64_t bad_requests = 0;   // answered with an error or warning status
};

class FoxgloveProtocol {
 public:
  /// `feed` (for the newest messages a new subscription gets) and `send` must outlive this object.
  FoxgloveProtocol(const lcm_wire::Schema& schema, const ViewFeed& feed, FoxgloveServerInfo info, Send send);

  /// A client connected: serverInfo, then the channels advertised so far.
  void onJoined(ClientId client);
  /// A text frame from the client: subscribe, unsubscribe, or a request answered with a status.
  void onText(ClientId client, const std::string& text);
  /// A binary frame from the client: publishing is not offered, so a status says so.
  void onBinary(ClientId client);
  void onLeft(ClientId client);
  /// A message the feed forwarded: advertised to every client if its channel is new (or changed type),
  /// sent to the clients subscribed to it.
  void onPublication(const Publication& publication);

  std::size_t clients() const { return clients_.size(); }
  const FoxgloveCounts& counts() const { return counts_; }

 private:
  struct Channel {
    std::uint32_t id = 0;
    std::string topic;
    std::string type_name;
    std::string schema;  // JSON Schema text, made once
  };
  struct Client {
    std::map<std::uint32_t, std::uint32_t> channel_of_subscription;
    std::map<std::uint32_t, std::uint32_t> subscription_of_channel;
  };

  /// The channel for `publication`'s LCM channel and type: a new id, advertised to every client, when its
  /// channel is new or its type changed (the old id is unadvertised then).
  const Channel& channelFor(const Publication& publication);
  std::string advertiseLine(const std::vector<const Channel*>& channels) const;
  void subscribe(ClientId client, Client& state, const YAML::Node& request);
  void unsubscribe(ClientId client, Client& state, const YAML::Node& request);
  /// Counts a bad request and answers it with a status of `level` (1 warning, 2 error).
  void refuse(ClientId client, int level, const std::string& message);
  WebFrame messageFrame(std::uint32_t subscription, const Publication& publication);

  const lcm_wire::Schema& schema_;
  const ViewFeed& feed_;
  FoxgloveServerInfo info_;
  Send send_;
  std::map<std::string, Channel> channels_;  // by LCM channel
  std::uint32_t next_channel_id_ = 1;
  std::map<ClientId, Client> clients_;
  FoxgloveCounts counts_;
};

}  // namespace ifar::view
