#include "tools/view/view_hub.hpp"

#include <utility>

#include "common/json_text.hpp"

namespace ifar::view {
namespace {

constexpr std::int64_t kStatisticsPeriodUs = 1'000'000;

}  // namespace

ViewHub::ViewHub(const lcm_wire::Schema& schema, FeedSettings settings, std::string hello_line, Send send,
                 FoxgloveServerInfo foxglove_info)
    : feed_(schema, settings),
      hello_line_(std::move(hello_line)),
      send_(std::move(send)),
      foxglove_(schema, feed_, std::move(foxglove_info), send_)
{
}

void ViewHub::onMessage(const std::string& channel, common::ByteView bytes, std::int64_t receive_utime)
{
  FeedUpdate update = feed_.onMessage(channel, bytes, receive_utime);
  std::vector<WebFrame> frames;
  std::vector<Publication> publications;
  if (update.reset) {
    frames.push_back(textFrame("{\"view\":\"reset\",\"reason\":" + common::jsonString(*update.reset) + "}"));
  }
  if (update.publication) {
    frames.push_back(textFrame(update.publication->page_line));
    publications.push_back(std::move(*update.publication));
  }
  forward(frames, publications);
}

void ViewHub::onClientEvent(const ClientEvent& event)
{
  if (event.endpoint == kFoxglovePath) {
    switch (event.kind) {
      case ClientEvent::Kind::kJoined:
        foxglove_.onJoined(event.client);
        break;
      case ClientEvent::Kind::kText:
        foxglove_.onText(event.client, event.text);
        break;
      case ClientEvent::Kind::kBinary:
        foxglove_.onBinary(event.client);
        break;
      case ClientEvent::Kind::kLeft:
        foxglove_.onLeft(event.client);
        break;
    }
    return;
  }
  switch (event.kind) {
    case ClientEvent::Kind::kJoined: {
      std::vector<WebFrame> frames{textFrame(hello_line_)};
      for (Publication& publication : feed_.latest()) {
        frames.push_back(textFrame(std::move(publication.page_line)));
      }
      frames.push_back(textFrame(feed_.trajectoryLine()));
      send_(event.client, frames);
      pages_.insert(event.client);
      break;
    }
    case ClientEvent::Kind::kLeft:
      pages_.erase(event.client);
      break;
    case ClientEvent::Kind::kText:
    case ClientEvent::Kind::kBinary:
      break;  // the page only listens
  }
}

void ViewHub::tick(std::int64_t now_utime)
{
  std::vector<Publication> publications = feed_.due(now_utime);
  std::vector<WebFrame> frames;
  frames.reserve(publications.size() + 1);
  for (const Publication& publication : publications) {
    frames.push_back(textFrame(publication.page_line));
  }
  if (now_utime - last_statistics_utime_ >= kStatisticsPeriodUs) {
    last_statistics_utime_ = now_utime;
    frames.push_back(textFrame(feed_.statisticsLine(now_utime)));
  }
  forward(frames, publications);
}

void ViewHub::forward(const std::vector<WebFrame>& frames, const std::vector<Publication>& publications)
{
  if (!frames.empty()) {
    for (const ClientId page : pages_) {
      send_(page, frames);
    }
  }
  for (const Publication& publication : publications) {
    foxglove_.onPublication(publication);
  }
}

}  // namespace ifar::view
