#pragma once
// Between the feed and the pages: a page that joins gets the hello line (the vehicle's size), the newest
// message of every channel and the trajectory so far before anything live; then every forwarded message,
// a reset notice when the log's time goes back, and once a second the channels' counts with the view's
// clock (the page ages heartbeats by it). Pages send nothing the hub needs. No sockets: what to send whom
// goes to a Send function (the web server's in ifar view, a recorder in tests). One thread.

#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "tools/view/view_feed.hpp"
#include "tools/view/web_server.hpp"

namespace ifar::view {

using Send = std::function<void(ClientId client, const std::vector<WebFrame>& frames)>;

class ViewHub {
 public:
  /// `hello_line` is the first frame every page gets; `send` must outlive the hub.
  ViewHub(const lcm_wire::Schema& schema, FeedSettings settings, std::string hello_line, Send send);

  void onMessage(const std::string& channel, common::ByteView bytes, std::int64_t receive_utime);
  void onClientEvent(const ClientEvent& event);
  /// Sends held-back messages that are due; the channels' counts once a second.
  void tick(std::int64_t now_utime);

  std::size_t pages() const { return pages_.size(); }
  const ViewFeed& feed() const { return feed_; }

 private:
  void broadcast(const std::vector<WebFrame>& frames) const;

  ViewFeed feed_;
  std::string hello_line_;
  Send send_;
  std::set<ClientId> pages_;
  std::int64_t last_statistics_utime_ = 0;
};

}  // namespace ifar::view
