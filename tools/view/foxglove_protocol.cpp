#include "tools/view/foxglove_protocol.hpp"

#include <optional>
#include <set>
#include <variant>

#include <yaml-cpp/yaml.h>

#include "common/json_text.hpp"
#include "tools/echo/json_schema.hpp"

namespace ifar::view {
namespace {

// Binary opcodes of the server's frames (spec: "Message Data").
constexpr std::uint8_t kMessageDataOpcode = 0x01;
constexpr int kStatusWarning = 1;
constexpr int kStatusError = 2;
// A subscription to every channel is a few kilobytes; anything far larger is not a request to read.
constexpr std::size_t kMaxRequestBytes = 1U << 20U;

// Client ops the spec has but this server offers no capability for: refused with a status naming them.
const std::set<std::string> kNotOfferedOps = {"advertise",
                                              "unadvertise",
                                              "getParameters",
                                              "setParameters",
                                              "subscribeParameterUpdates",
                                              "unsubscribeParameterUpdates",
                                              "subscribeConnectionGraph",
                                              "unsubscribeConnectionGraph",
                                              "fetchAsset"};

void appendLittleEndian(std::string& bytes, std::uint64_t value, std::size_t width)
{
  for (std::size_t index = 0; index < width; ++index) {
    bytes += static_cast<char>((value >> (8U * index)) & 0xFFU);
  }
}

/// Client messages are JSON; yaml-cpp (the project's YAML library) reads them, JSON being YAML's flow style.
/// A message that does not parse, or is not an object with a string "op", is a std::string: why.
std::variant<YAML::Node, std::string> parseRequest(const std::string& text)
{
  if (text.size() > kMaxRequestBytes) {
    return "longer than " + std::to_string(kMaxRequestBytes) + " bytes";
  }
  YAML::Node node;
  try {
    node = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    return "not JSON (" + error.msg + ")";
  }
  if (!node.IsMap()) {
    return std::string("not a JSON object with an \"op\"");
  }
  const YAML::Node op = node["op"];
  if (!op || !op.IsScalar()) {
    return std::string("no \"op\" string");
  }
  return node;
}

/// `node` as a u32 id, or nothing (missing, negative, too large, not a number).
std::optional<std::uint32_t> idOf(const YAML::Node& node)
{
  if (!node || !node.IsScalar()) {
    return std::nullopt;
  }
  try {
    return node.as<std::uint32_t>();
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
}

}  // namespace

FoxgloveProtocol::FoxgloveProtocol(const lcm_wire::Schema& schema, const ViewFeed& feed,
                                   FoxgloveServerInfo info, Send send)
    : schema_(schema), feed_(feed), info_(std::move(info)), send_(std::move(send))
{
}

void FoxgloveProtocol::onJoined(ClientId client)
{
  clients_[client] = Client{};
  std::string metadata;
  for (const auto& [key, value] : info_.metadata) {
    metadata += (metadata.empty() ? "" : ",") + common::jsonString(key) + ":" + common::jsonString(value);
  }
  // No optional capability: the client only subscribes, and message times are the view's receive times.
  std::string server_info = R"({"op":"serverInfo","name":)" + common::jsonString(info_.name) +
                            R"(,"capabilities":[],"metadata":{)" + metadata + "}}";
  std::vector<const Channel*> channels;
  channels.reserve(channels_.size());
  for (const auto& [name, channel] : channels_) {
    channels.push_back(&channel);
  }
  send_(client, {textFrame(std::move(server_info)), textFrame(advertiseLine(channels))});
}

void FoxgloveProtocol::onLeft(ClientId client)
{
  clients_.erase(client);
}

void FoxgloveProtocol::onBinary(ClientId client)
{
  if (clients_.count(client) > 0) {
    refuse(client, kStatusError, "binary messages refused: this server offers no clientPublish or services");
  }
}

void FoxgloveProtocol::onText(ClientId client, const std::string& text)
{
  const auto found = clients_.find(client);
  if (found == clients_.end()) {
    return;
  }
  std::variant<YAML::Node, std::string> parsed = parseRequest(text);
  if (std::holds_alternative<std::string>(parsed)) {
    refuse(client, kStatusError, "request refused: " + std::get<std::string>(parsed));
    return;
  }
  const YAML::Node& request = std::get<YAML::Node>(parsed);
  const std::string op = request["op"].as<std::string>();
  try {
    if (op == "subscribe") {
      subscribe(client, found->second, request);
    } else if (op == "unsubscribe") {
      unsubscribe(client, found->second, request);
    } else if (kNotOfferedOps.count(op) > 0) {
      refuse(client, kStatusError,
             "op \"" + op + "\" refused: this server offers only subscribe and unsubscribe");
    } else {
      refuse(client, kStatusError, "unknown op \"" + op + "\"");
    }
  } catch (const YAML::Exception& error) {
    // The handlers read only what they checked the shape of; should one get past them anyway, the request is
    // still only refused.
    refuse(client, kStatusError, "op \"" + op + "\" refused: " + error.msg);
  }
}

void FoxgloveProtocol::subscribe(ClientId client, Client& state, const YAML::Node& request)
{
  const YAML::Node subscriptions = request["subscriptions"];
  if (!subscriptions || !subscriptions.IsSequence()) {
    refuse(client, kStatusError, "subscribe refused: no \"subscriptions\" array");
    return;
  }
  std::vector<WebFrame> frames;
  for (const YAML::Node& entry : subscriptions) {
    const std::optional<std::uint32_t> id = entry.IsMap() ? idOf(entry["id"]) : std::nullopt;
    const std::optional<std::uint32_t> channel_id = entry.IsMap() ? idOf(entry["channelId"]) : std::nullopt;
    if (!id || !channel_id) {
      refuse(client, kStatusError,
             "subscription refused: it needs an \"id\" and a \"channelId\", numbers from 0 to 4294967295");
      continue;
    }
    const Channel* channel = nullptr;
    for (const auto& [name, candidate] : channels_) {
      if (candidate.id == *channel_id) {
        channel = &candidate;
      }
    }
    if (channel == nullptr) {
      refuse(client, kStatusError,
             "subscription " + std::to_string(*id) + " refused: no channel " + std::to_string(*channel_id) +
                 " is advertised");
      continue;
    }
    if (state.channel_of_subscription.count(*id) > 0) {
      refuse(client, kStatusError, "subscription " + std::to_string(*id) + " refused: that id is in use");
      continue;
    }
    if (const auto taken = state.subscription_of_channel.find(*channel_id);
        taken != state.subscription_of_channel.end()) {
      refuse(client, kStatusError,
             "subscription " + std::to_string(*id) + " refused: channel " + std::to_string(*channel_id) +
                 " (" + channel->topic + ") is subscribed already, as subscription " +
                 std::to_string(taken->second));
      continue;
    }
    state.channel_of_subscription[*id] = *channel_id;
    state.subscription_of_channel[*channel_id] = *id;
    // What the view holds of it, so a graph or a goal published before the client came shows at once.
    for (const Publication& publication : feed_.latestOf(channel->topic)) {
      if (publication.type_name == channel->type_name) {
        frames.push_back(messageFrame(*id, publication));
      }
    }
  }
  if (!frames.empty()) {
    send_(client, frames);
  }
}

void FoxgloveProtocol::unsubscribe(ClientId client, Client& state, const YAML::Node& request)
{
  const YAML::Node ids = request["subscriptionIds"];
  if (!ids || !ids.IsSequence()) {
    refuse(client, kStatusError, "unsubscribe refused: no \"subscriptionIds\" array");
    return;
  }
  for (const YAML::Node& entry : ids) {
    const std::optional<std::uint32_t> id = idOf(entry);
    const auto found = id ? state.channel_of_subscription.find(*id) : state.channel_of_subscription.end();
    if (found == state.channel_of_subscription.end()) {
      refuse(client, kStatusWarning,
             "unsubscribe: " +
                 (id ? "no subscription " + std::to_string(*id) : std::string("an id is not a number")));
      continue;
    }
    state.subscription_of_channel.erase(found->second);
    state.channel_of_subscription.erase(found);
  }
}

void FoxgloveProtocol::refuse(ClientId client, int level, const std::string& message)
{
  ++counts_.bad_requests;
  send_(client, {textFrame(R"({"op":"status","level":)" + std::to_string(level) +
                           ",\"message\":" + common::jsonString(message) + "}")});
}

WebFrame FoxgloveProtocol::messageFrame(std::uint32_t subscription, const Publication& publication)
{
  ++counts_.messages_sent;
  WebFrame frame{true, {}};
  frame.bytes.reserve(13 + publication.message_json.size());
  frame.bytes += static_cast<char>(kMessageDataOpcode);
  appendLittleEndian(frame.bytes, subscription, 4);
  const std::int64_t nanoseconds = publication.receive_utime > 0 ? publication.receive_utime * 1000 : 0;
  appendLittleEndian(frame.bytes, static_cast<std::uint64_t>(nanoseconds), 8);
  frame.bytes += publication.message_json;
  return frame;
}

void FoxgloveProtocol::onPublication(const Publication& publication)
{
  const Channel& channel = channelFor(publication);
  for (const auto& [client, state] : clients_) {
    const auto subscribed = state.subscription_of_channel.find(channel.id);
    if (subscribed != state.subscription_of_channel.end()) {
      send_(client, {messageFrame(subscribed->second, publication)});
    }
  }
}

const FoxgloveProtocol::Channel& FoxgloveProtocol::channelFor(const Publication& publication)
{
  const auto found = channels_.find(publication.channel);
  if (found != channels_.end() && found->second.type_name == publication.type_name) {
    return found->second;
  }
  if (found != channels_.end()) {
    // Another type on the same LCM channel: another schema, so another channel id.
    const std::uint32_t old_id = found->second.id;
    for (auto& [client, state] : clients_) {
      if (const auto subscribed = state.subscription_of_channel.find(old_id);
          subscribed != state.subscription_of_channel.end()) {
        state.channel_of_subscription.erase(subscribed->second);
        state.subscription_of_channel.erase(subscribed);
      }
      send_(client, {textFrame(R"({"op":"unadvertise","channelIds":[)" + std::to_string(old_id) + "]}")});
    }
  }
  Channel& channel = channels_[publication.channel];
  channel.id = next_channel_id_++;
  channel.topic = publication.channel;
  channel.type_name = publication.type_name;
  const lcm_wire::StructType* type = schema_.find(publication.type_name);
  channel.schema = type != nullptr ? echo::jsonSchemaOf(schema_, *type) : std::string(R"({"type":"object"})");
  const std::string advertise = advertiseLine({&channel});
  for (const auto& [client, state] : clients_) {
    send_(client, {textFrame(advertise)});
  }
  return channel;
}

std::string FoxgloveProtocol::advertiseLine(const std::vector<const Channel*>& channels) const
{
  std::string entries;
  for (const Channel* channel : channels) {
    entries += std::string(entries.empty() ? "" : ",") + R"({"id":)" + std::to_string(channel->id) +
               R"(,"topic":)" + common::jsonString(channel->topic) + R"(,"encoding":"json","schemaName":)" +
               common::jsonString(channel->type_name) + R"(,"schema":)" +
               common::jsonString(channel->schema) + R"(,"schemaEncoding":"jsonschema"})";
  }
  return R"({"op":"advertise","channels":[)" + entries + "]}";
}

}  // namespace ifar::view
