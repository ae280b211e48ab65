#pragma once
// Between the feed and the pages: a page that joins gets the hello line (the vehicle's size), the newest
// message of every channel and the trajectory so far before anything live; then every forwarded message,
// a reset notice when the log's time goes back, and once a second the channels' counts with the view's
// clock (the page ages heartbeats by it). Pages send nothing the hub needs. Clients on the Foxglove path
// (kFoxglovePath) are the Foxglove protocol's: they get the same forwarded messages when they subscribe. No
// sockets: what to send whom goes to a Send function (the web server's in ifar view, a recorder in tests).
// One thread.

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "tools/view/foxglove_protocol.hpp"
#include "tools/view/view_feed.hpp"
#include "tools/view/web_server.hpp"

namespace ifar::view {

class ViewHub {
 public:
  /// `hello_line` is the first frame every page gets; `send` must outlive the hub; `foxglove_info` is what
  /// Foxglove clients are told of the server.
  ViewHub(const lcm_wire::Schema& schema, FeedSettings settings, std::string hello_line, Send send,
          FoxgloveServerInfo foxglove_info = {});

  void onMessage(const std::string& channel, common::ByteView bytes, std::int64_t receive_utime);
  void onClientEvent(const ClientEvent& event);
  /// Sends held-back messages that are due; the channels' counts once a second.
  void tick(std::int64_t now_utime);

  std::size_t pages() const { return pages_.size(); }
  const ViewFeed& feed() const { return feed_; }
  const FoxgloveProtocol& foxglove() const { return foxglove_; }

 private:
  /// To every page, and each publication among them to the Foxglove clients subscribed to its channel.
  void forward(const std::vector<WebFrame>& frames, const std::vector<Publication>& publications);

  ViewFeed feed_;
  std::string hello_line_;
  Send send_;
  std::set<ClientId> pages_;
  std::int64_t last_statistics_utime_ = 0;
  FoxgloveProtocol foxglove_;
};

}  // namespace ifar::view
