#include "tools/view/foxglove_protocol.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "ifar/goal_t.hpp"
#include "ifar/heartbeat_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "lcmtypes/message_schema.hpp"
#include "tools/echo/message_format.hpp"
#include "tools/view/view_hub.hpp"

namespace ifar::view {
namespace {

constexpr std::int64_t kStart = 1'700'000'000'123'456;
const std::string kFoxglove(kFoxglovePath);

template <typename Message>
std::vector<std::uint8_t> encoded(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

goal_t goalAt(double x)
{
  goal_t goal{};
  goal.utime = kStart;
  goal.goal_id = 17;
  goal.x = x;
  goal.y = -2.25;
  return goal;
}

/// The message as `ifar echo --json` prints its "message" object, decoded here on its own.
template <typename Message>
std::string echoJson(const Message& message)
{
  const std::vector<std::uint8_t> bytes = encoded(message);
  const echo::MessageTypes types(lcmtypes::messageSchema());
  const common::ByteView view(bytes.data(), bytes.size());
  const lcm_wire::StructType* type = types.typeOf(view);
  EXPECT_NE(type, nullptr);
  return echo::jsonObject(std::get<echo::Members>(types.decode(*type, view)));
}

/// A Message Data frame as the spec lays it out: opcode 0x01, u32 LE subscription id, u64 LE time in ns.
std::string messageData(std::uint32_t subscription, std::int64_t receive_utime, const std::string& payload)
{
  std::string bytes(1, '\x01');
  for (unsigned shift = 0; shift < 32; shift += 8) {
    bytes += static_cast<char>((subscription >> shift) & 0xFFU);
  }
  const auto nanoseconds = static_cast<std::uint64_t>(receive_utime) * 1000U;
  for (unsigned shift = 0; shift < 64; shift += 8) {
    bytes += static_cast<char>((nanoseconds >> shift) & 0xFFU);
  }
  return bytes + payload;
}

class FoxgloveProtocolTest : public ::testing::Test {
 protected:
  FoxgloveProtocolTest()
      : hub(
            lcmtypes::messageSchema(), settings(), "{\"view\":\"hello\"}",
            [this](ClientId client, const std::vector<WebFrame>& frames) {
              for (const WebFrame& frame : frames) {
                sent[client].push_back(frame);
              }
            },
            FoxgloveServerInfo{"ifar view", {{"lcm_url", "udpm://239.255.76.67:7999?ttl=0"}}})
  {
  }

  static FeedSettings settings()
  {
    FeedSettings chosen;
    chosen.max_rate_hz = 10.0;  // one message per 100 ms
    return chosen;
  }

  template <typename Message>
  void publish(const std::string& channel, const Message& message, std::int64_t receive_utime)
  {
    const std::vector<std::uint8_t> bytes = encoded(message);
    hub.onMessage(channel, common::ByteView(bytes.data(), bytes.size()), receive_utime);
  }

  void join(ClientId client, const std::string& endpoint = kFoxglove)
  {
    hub.onClientEvent({ClientEvent::Kind::kJoined, client, "127.0.0.1", endpoint});
  }

  void say(ClientId client, const std::string& text)
  {
    hub.onClientEvent({ClientEvent::Kind::kText, client, text, kFoxglove});
  }

  /// The frames `client` got since the last call.
  std::vector<WebFrame> take(ClientId client)
  {
    std::vector<WebFrame> frames;
    frames.swap(sent[client]);
    return frames;
  }

  static YAML::Node json(const WebFrame& frame)
  {
    EXPECT_FALSE(frame.binary);
    return YAML::Load(frame.bytes);
  }

  /// The one channel advertised in `frame`.
  static YAML::Node advertised(const WebFrame& frame)
  {
    const YAML::Node node = json(frame);
    EXPECT_EQ(node["op"].as<std::string>(), "advertise") << frame.bytes;
    EXPECT_EQ(node["channels"].size(), 1U) << frame.bytes;
    return node["channels"][0];
  }

  /// A single status frame of `level` whose message contains `words`; the count of bad requests one more.
  void expectRefused(ClientId client, int level, const std::string& words)
  {
    const std::vector<WebFrame> frames = take(client);
    ASSERT_EQ(frames.size(), 1U);
    const YAML::Node status = json(frames[0]);
    EXPECT_EQ(status["op"].as<std::string>(), "status");
    EXPECT_EQ(status["level"].as<int>(), level);
    EXPECT_NE(status["message"].as<std::string>().find(words), std::string::npos) << frames[0].bytes;
  }

  std::map<ClientId, std::vector<WebFrame>> sent;
  ViewHub hub;
};

TEST_F(FoxgloveProtocolTest, AClientGetsServerInfoFirstThenTheChannelsSoFarWithTheirSchemas)
{
  publish("GOAL", goalAt(3.5), kStart);
  join(5);
  const std::vector<WebFrame> frames = take(5);
  ASSERT_EQ(frames.size(), 2U);
  const YAML::Node info = json(frames[0]);
  EXPECT_EQ(info["op"].as<std::string>(), "serverInfo");
  EXPECT_EQ(info["name"].as<std::string>(), "ifar view");
  EXPECT_TRUE(info["capabilities"].IsSequence());
  EXPECT_EQ(info["capabilities"].size(), 0U);
  EXPECT_EQ(info["metadata"]["lcm_url"].as<std::string>(), "udpm://239.255.76.67:7999?ttl=0");

  const YAML::Node channel = advertised(frames[1]);
  EXPECT_EQ(channel["id"].as<int>(), 1);
  EXPECT_EQ(channel["topic"].as<std::string>(), "GOAL");
  EXPECT_EQ(channel["encoding"].as<std::string>(), "json");
  EXPECT_EQ(channel["schemaName"].as<std::string>(), "goal_t");
  EXPECT_EQ(channel["schemaEncoding"].as<std::string>(), "jsonschema");
  const YAML::Node schema = YAML::Load(channel["schema"].as<std::string>());
  EXPECT_EQ(schema["type"].as<std::string>(), "object");
  EXPECT_EQ(schema["title"].as<std::string>(), "goal_t");
  EXPECT_EQ(schema["properties"]["utime"]["type"].as<std::string>(), "integer");
  EXPECT_EQ(schema["properties"]["goal_id"]["type"].as<std::string>(), "integer");
  EXPECT_EQ(schema["properties"]["x"]["type"].as<std::string>(), "number");
  EXPECT_EQ(schema["properties"]["y"]["type"].as<std::string>(), "number");
  EXPECT_EQ(schema["properties"]["cancel"]["type"].as<std::string>(), "boolean");
  EXPECT_EQ(schema["required"].size(), 5U);
  EXPECT_EQ(hub.foxglove().clients(), 1U);
  EXPECT_EQ(hub.pages(), 0U);  // a Foxglove client is no page
}

TEST_F(FoxgloveProtocolTest, ANewChannelIsAdvertisedOnceWhenItFirstCarriesAMessage)
{
  join(5);
  const std::vector<WebFrame> greeting = take(5);
  ASSERT_EQ(greeting.size(), 2U);
  EXPECT_EQ(greeting[1].bytes, "{\"op\":\"advertise\",\"channels\":[]}");  // always one, empty or not
  publish("GOAL", goalAt(1.0), kStart);
  std::vector<WebFrame> frames = take(5);
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_EQ(advertised(frames[0])["topic"].as<std::string>(), "GOAL");
  publish("GOAL", goalAt(2.0), kStart + 1);
  EXPECT_TRUE(take(5).empty());  // known already, and not subscribed
  pose_t pose{};
  pose.orientation[0] = 1.0;
  publish("POSE", pose, kStart + 2);
  frames = take(5);
  ASSERT_EQ(frames.size(), 1U);
  const YAML::Node channel = advertised(frames[0]);
  EXPECT_EQ(channel["id"].as<int>(), 2);
  const YAML::Node position = YAML::Load(channel["schema"].as<std::string>())["properties"]["position"];
  EXPECT_EQ(position["type"].as<std::string>(), "array");
  EXPECT_EQ(position["items"]["type"].as<std::string>(), "number");
  EXPECT_EQ(position["minItems"].as<int>(), 3);
  EXPECT_EQ(position["maxItems"].as<int>(), 3);
}

TEST_F(FoxgloveProtocolTest, ASubscriptionGetsTheNewestAtOnceThenEachMessageAsExactMessageData)
{
  publish("GOAL", goalAt(3.5), kStart);
  join(5);
  take(5);
  // An id with four different bytes, so their order shows.
  say(5, R"({"op":"subscribe","subscriptions":[{"id":16909060,"channelId":1}]})");
  std::vector<WebFrame> frames = take(5);
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_TRUE(frames[0].binary);
  EXPECT_EQ(frames[0].bytes, messageData(0x01020304U, kStart, echoJson(goalAt(3.5))));
  EXPECT_EQ(static_cast<std::uint8_t>(frames[0].bytes[1]), 0x04U);  // little-endian
  publish("GOAL", goalAt(4.75), kStart + 250);
  frames = take(5);
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_EQ(frames[0].bytes, messageData(0x01020304U, kStart + 250, echoJson(goalAt(4.75))));
  EXPECT_NE(frames[0].bytes.find("\"x\":4.75,\"y\":-2.25"), std::string::npos);
  EXPECT_EQ(hub.foxglove().counts().messages_sent, 2);
  EXPECT_EQ(hub.foxglove().counts().bad_requests, 0);
}

TEST_F(FoxgloveProtocolTest, UnsubscribeStopsTheMessagesAndOnlySubscribedChannelsAreSent)
{
  join(5);
  join(6);
  publish("GOAL", goalAt(1.0), kStart);
  publish("HEARTBEAT", heartbeat_t{}, kStart);
  take(5);
  take(6);
  say(5, R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":1}]})");
  take(5);
  publish("HEARTBEAT", heartbeat_t{}, kStart + 1);
  EXPECT_TRUE(take(5).empty());  // not subscribed to the heartbeats
  publish("GOAL", goalAt(2.0), kStart + 2);
  EXPECT_EQ(take(5).size(), 1U);
  EXPECT_TRUE(take(6).empty());  // subscriptions are each client's own
  say(5, R"({"op":"unsubscribe","subscriptionIds":[0]})");
  EXPECT_TRUE(take(5).empty());  // no answer to a good request
  publish("GOAL", goalAt(3.0), kStart + 3);
  EXPECT_TRUE(take(5).empty());
  // The id is free again, for another channel.
  say(5, R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":2}]})");
  EXPECT_EQ(take(5).size(), 1U);  // the newest heartbeat
  EXPECT_EQ(hub.foxglove().counts().bad_requests, 0);
}

TEST_F(FoxgloveProtocolTest, PagesAndFoxgloveClientsGetEachTheirOwn)
{
  join(1, "/ws");
  join(5);
  take(1);
  take(5);
  say(5, R"({"op":"subscribe","subscriptions":[{"id":3,"channelId":1}]})");  // not yet advertised
  take(5);
  publish("GOAL", goalAt(1.0), kStart);
  hub.tick(kStart + 2'000'000);  // the channels' counts: the page's only
  const std::vector<WebFrame> page = take(1);
  ASSERT_EQ(page.size(), 2U);
  EXPECT_NE(page[0].bytes.find("\"channel\":\"GOAL\""), std::string::npos);
  EXPECT_NE(page[1].bytes.find("\"view\":\"channels\""), std::string::npos);
  const std::vector<WebFrame> foxglove = take(5);
  ASSERT_EQ(foxglove.size(), 1U);  // the advertisement only
  EXPECT_EQ(advertised(foxglove[0])["topic"].as<std::string>(), "GOAL");
}

TEST_F(FoxgloveProtocolTest, FastChannelsAreThinnedAsForThePageAndTheLastOfABurstStillGoes)
{
  join(5);
  pose_t pose{};
  pose.orientation[0] = 1.0;
  publish("POSE", pose, kStart);
  say(5, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})");
  take(5);
  for (int step = 1; step <= 10; ++step) {  // 50 Hz for 200 ms against a 10 Hz limit
    pose.utime = kStart + step * 20'000;
    pose.position[0] = step;
    publish("POSE", pose, kStart + step * 20'000);
  }
  EXPECT_EQ(take(5).size(), 2U);  // at 100 and 200 ms
  pose.position[0] = 11.0;
  publish("POSE", pose, kStart + 220'000);  // held back
  EXPECT_TRUE(take(5).empty());
  hub.tick(kStart + 300'000);
  const std::vector<WebFrame> frames = take(5);
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_NE(frames[0].bytes.find("\"position\":[11,"), std::string::npos);
  EXPECT_EQ(frames[0].bytes.substr(0, 13), messageData(1, kStart + 220'000, ""));  // its own receive time
}

TEST_F(FoxgloveProtocolTest, RawStreamsAreNotAdvertised)
{
  join(5);
  take(5);
  velodyne_packet_t packet{};
  packet.size = 4;
  packet.data = {1, 2, 3, 4};
  publish("VELODYNE_PACKET", packet, kStart);
  EXPECT_TRUE(take(5).empty());
}

TEST_F(FoxgloveProtocolTest, AnotherTypeOnAChannelIsAnotherChannelAndEndsItsSubscriptions)
{
  join(5);
  publish("GOAL", goalAt(1.0), kStart);
  say(5, R"({"op":"subscribe","subscriptions":[{"id":9,"channelId":1}]})");
  take(5);
  publish("GOAL", heartbeat_t{}, kStart + 1);
  const std::vector<WebFrame> frames = take(5);
  ASSERT_EQ(frames.size(), 2U);
  EXPECT_EQ(frames[0].bytes, "{\"op\":\"unadvertise\",\"channelIds\":[1]}");
  const YAML::Node channel = advertised(frames[1]);
  EXPECT_EQ(channel["id"].as<int>(), 2);
  EXPECT_EQ(channel["schemaName"].as<std::string>(), "heartbeat_t");
  publish("GOAL", heartbeat_t{}, kStart + 2);
  EXPECT_TRUE(take(5).empty());
  say(5, R"({"op":"subscribe","subscriptions":[{"id":9,"channelId":2}]})");  // id 9 is free again
  EXPECT_EQ(take(5).size(), 1U);
}

TEST_F(FoxgloveProtocolTest, BadRequestsAreCountedAndAnsweredWithAStatusNeverMore)
{
  publish("GOAL", goalAt(1.0), kStart);
  join(5);
  take(5);
  say(5, "{\"op\":");
  expectRefused(5, 2, "not JSON");
  say(5, "[1,2,3]");
  expectRefused(5, 2, "not a JSON object");
  say(5, R"({"subscriptions":[]})");
  expectRefused(5, 2, "no \"op\"");
  say(5, R"({"op":"dance"})");
  expectRefused(5, 2, "unknown op \"dance\"");
  say(5, R"({"op":"getParameters","parameterNames":[]})");
  expectRefused(5, 2, "offers only subscribe and unsubscribe");
  say(5, R"({"op":"subscribe"})");
  expectRefused(5, 2, "no \"subscriptions\" array");
  say(5, R"({"op":"subscribe","subscriptions":[7]})");
  expectRefused(5, 2, "needs an \"id\" and a \"channelId\"");
  say(5, R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":1}]})");
  expectRefused(5, 2, "needs an \"id\" and a \"channelId\"");
  say(5, R"({"op":"subscribe","subscriptions":[{"id":4294967296,"channelId":1}]})");
  expectRefused(5, 2, "needs an \"id\" and a \"channelId\"");
  say(5, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":999}]})");
  expectRefused(5, 2, "no channel 999 is advertised");
  say(5, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})");
  EXPECT_EQ(take(5).size(), 1U);  // the newest goal
  say(5, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})");
  expectRefused(5, 2, "that id is in use");
  say(5, R"({"op":"subscribe","subscriptions":[{"id":2,"channelId":1}]})");
  expectRefused(5, 2, "is subscribed already, as subscription 1");
  say(5, R"({"op":"unsubscribe","subscriptionIds":[77]})");
  expectRefused(5, 1, "no subscription 77");
  say(5, R"({"op":"unsubscribe","subscriptionIds":{"a":1}})");
  expectRefused(5, 2, "no \"subscriptionIds\" array");
  hub.onClientEvent({ClientEvent::Kind::kBinary, 5, std::string("\x01\x00\x00\x00\x00{}", 7), kFoxglove});
  expectRefused(5, 2, "binary messages refused");
  say(5, R"({"op":"subscribe","subscriptions":[{"id":3,"channelId":1,"pad":")" + std::string(2U << 20U, 'x') +
             "\"}]}");
  expectRefused(5, 2, "longer than 1048576 bytes");
  say(5, std::string(50000, '[') + std::string(50000, ']'));  // deeper than the parser goes
  expectRefused(5, 2, "not JSON");
  EXPECT_EQ(hub.foxglove().counts().bad_requests, 17);
  // Still subscribed, still served.
  publish("GOAL", goalAt(2.0), kStart + 1);
  EXPECT_EQ(take(5).size(), 1U);
  // A client that left gets nothing, and what it said late is dropped.
  hub.onClientEvent({ClientEvent::Kind::kLeft, 5, {}, kFoxglove});
  say(5, R"({"op":"dance"})");
  publish("GOAL", goalAt(3.0), kStart + 2);
  EXPECT_TRUE(take(5).empty());
  EXPECT_EQ(hub.foxglove().clients(), 0U);
}

}  // namespace
}  // namespace ifar::view
