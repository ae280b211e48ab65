// The checked decode of project messages: the schema built from lcmtypes/*.lcm agrees with LCM's
// generated code on every sample and every cut of one, and messages claiming more than their bytes
// hold are refused before anything is allocated for them.

#include "lcmtypes/checked_decode.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "ifar/heartbeat_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "lcmtypes/samples/sample_messages.hpp"
#include "testing/allocation_tracker.hpp"

namespace {

using ifar::lcmtypes_samples::allSampleMessages;

template <typename Message>
std::vector<std::uint8_t> encode(const Message& message)
{
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  EXPECT_EQ(message.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  return bytes;
}

void writeInt32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::int32_t value)
{
  const auto bits = static_cast<std::uint32_t>(value);
  for (std::size_t index = 0; index < 4; ++index) {
    bytes[offset + index] = static_cast<std::uint8_t>(bits >> (8 * (3 - index)));
  }
}

TEST(CheckedDecode, TheSchemaHoldsEveryTypeAndPassesEverySample)
{
  const auto& schema = ifar::lcmtypes::messageSchema();
  EXPECT_EQ(schema.types().size(), ifar::lcmtypes::lcmDefinitions().size());
  for (const auto& sample : allSampleMessages()) {
    const auto* type = schema.find(sample.type_name);
    ASSERT_NE(type, nullptr) << sample.type_name;
    EXPECT_EQ(ifar::lcm_wire::findUnbackedClaim(schema, *type, sample.encoded), std::nullopt)
        << sample.type_name;
  }
}

// Every proper prefix of every sample fails to decode, whether the claim check or LCM's decode refuses it.
TEST(CheckedDecode, EveryCutOfEverySampleIsRefused)
{
  for (const auto& sample : allSampleMessages()) {
    for (std::size_t length = 0; length < sample.encoded.size(); ++length) {
      const std::vector<std::uint8_t> cut(sample.encoded.begin(),
                                          sample.encoded.begin() + static_cast<std::ptrdiff_t>(length));
      std::vector<std::uint8_t> reencoded;
      EXPECT_FALSE(sample.reencode(cut, reencoded)) << sample.type_name << " cut to " << length << " bytes";
    }
  }
}

TEST(CheckedDecode, APacketClaimingAGigabyteAllocatesNothingForIt)
{
  ifar::velodyne_packet_t packet{};
  packet.size = 3;
  packet.data = {7, 8, 9};
  std::vector<std::uint8_t> bytes = encode(packet);
  constexpr std::size_t kSizeOffset = 8 + 8 + 4 + 4;  // hash, utime, device time, port
  writeInt32(bytes, kSizeOffset, 1'000'000'000);

  ifar::velodyne_packet_t decoded;
  ifar::test_support::startTrackingAllocations();
  const ifar::lcmtypes::DecodeResult result = ifar::lcmtypes::decodeLcm(decoded, bytes.data(), bytes.size());
  EXPECT_LT(ifar::test_support::stopTrackingAllocations(), 64U * 1024U);
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.error,
            "velodyne_packet_t.data claims 1000000000 elements of at least 1 bytes at byte 28, 3 bytes left");
  EXPECT_EQ(decoded.data.capacity(), 0U);
}

TEST(CheckedDecode, ANestedClaimIsNamedAndRefusedBeforeTheDecode)
{
  ifar::path_t path{};
  path.num_push_plans = 1;
  path.push_plans.resize(1);
  std::vector<std::uint8_t> bytes = encode(path);
  // hash, utime, goal_id, sequence, valid, length_m, cost, num_waypoints, num_push_plans; then the plan's
  // utime, object_id, from_vertex, to_vertex, contact_edge, contact pose: num_controls at byte 117.
  constexpr std::size_t kNumControlsOffset = 8 + 8 + 8 + 8 + 1 + 8 + 8 + 4 + 4 + 8 + 8 + 8 + 8 + 4 + 24;
  writeInt32(bytes, kNumControlsOffset, 500'000'000);

  ifar::path_t decoded;
  ifar::test_support::startTrackingAllocations();
  const ifar::lcmtypes::DecodeResult result = ifar::lcmtypes::decodeLcm(decoded, bytes.data(), bytes.size());
  EXPECT_LT(ifar::test_support::stopTrackingAllocations(), 64U * 1024U);
  EXPECT_EQ(
      result.error,
      "path_t.push_plans[0].controls claims 500000000 elements of at least 77 bytes at byte 121, 40 bytes "
      "left");
}

TEST(CheckedDecode, AStringClaimingNoBytesIsRefused)
{
  ifar::heartbeat_t beat{};
  beat.process = "planner";
  std::vector<std::uint8_t> bytes = encode(beat);
  writeInt32(bytes, 16, 0);  // the length of `process`, after the hash and utime
  ifar::heartbeat_t decoded;
  EXPECT_EQ(ifar::lcmtypes::decodeLcm(decoded, bytes.data(), bytes.size()).error,
            "heartbeat_t.process claims a string of 0 bytes (its NUL included) at byte 16, " +
                std::to_string(bytes.size() - 20) + " bytes left");
}

TEST(CheckedDecode, AnotherTypesBytesAreNamedAsSuch)
{
  const std::vector<std::uint8_t> bytes = encode(ifar::pose_t{});
  ifar::path_t decoded;
  EXPECT_EQ(ifar::lcmtypes::decodeLcm(decoded, bytes.data(), bytes.size()).error,
            "not a path_t: its type hash differs");
}

}  // namespace
