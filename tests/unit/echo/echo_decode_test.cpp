// ifar echo's decoding without a bus: the fingerprint computed from each .lcm definition is the one
// lcm-gen's code returns (every type of fingerprints.txt), every sample message decodes to its values, the
// text and JSON are exact, and bytes that claim more than they hold are refused naming the member.

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "lcmtypes/message_schema.hpp"
#include "lcmtypes/samples/sample_messages.hpp"
#include "tools/echo/message_format.hpp"
#include "tools/echo/message_value.hpp"
#include "tools/echo/schema_fingerprint.hpp"

namespace ifar::echo {
namespace {

using lcmtypes_samples::allSampleMessages;
using lcmtypes_samples::SampleMessage;

const SampleMessage& sampleOn(const std::string& channel)
{
  static const std::vector<SampleMessage> samples = allSampleMessages();
  for (const auto& sample : samples) {
    if (sample.channel == channel) {
      return sample;
    }
  }
  throw std::runtime_error("no sample on " + channel);
}

Members decoded(const SampleMessage& sample)
{
  const MessageTypes types(lcmtypes::messageSchema());
  const lcm_wire::StructType* type = types.typeOf(common::ByteView(sample.encoded));
  EXPECT_NE(type, nullptr) << sample.type_name;
  if (type == nullptr) {
    return {};
  }
  EXPECT_EQ(type->name, sample.type_name);
  auto result = types.decode(*type, common::ByteView(sample.encoded));
  EXPECT_TRUE(std::holds_alternative<Members>(result)) << std::get<std::string>(result);
  return std::holds_alternative<Members>(result) ? std::get<Members>(result) : Members{};
}

TEST(SchemaFingerprint, EveryTypeHasTheFingerprintOfFingerprintsTxt)
{
  std::ifstream file(std::string(IFAR_SOURCE_DIR) + "/lcmtypes/fingerprints.txt");
  ASSERT_TRUE(file.good());
  std::map<std::string, std::int64_t> listed;
  std::string line;
  while (std::getline(file, line)) {
    if (line.empty() || line[0] == '#') {
      continue;
    }
    std::istringstream fields(line);
    std::string name;
    std::string hex;
    fields >> name >> hex;
    listed[name] = static_cast<std::int64_t>(std::stoull(hex, nullptr, 16));
  }
  const lcm_wire::Schema& schema = lcmtypes::messageSchema();
  ASSERT_EQ(listed.size(), schema.types().size());
  ASSERT_EQ(listed.size(), 28U);
  for (const auto& type : schema.types()) {
    ASSERT_EQ(listed.count(type.name), 1U) << type.name;
    EXPECT_EQ(fingerprintOf(schema, type), listed[type.name]) << type.name;
  }
}

TEST(SchemaFingerprint, EqualsGetHashOfEveryGeneratedType)
{
  const lcm_wire::Schema& schema = lcmtypes::messageSchema();
  for (const auto& sample : allSampleMessages()) {
    const lcm_wire::StructType* type = schema.find(sample.type_name);
    ASSERT_NE(type, nullptr) << sample.type_name;
    EXPECT_EQ(fingerprintOf(schema, *type), sample.fingerprint) << sample.type_name;
  }
}

TEST(MessageTypesTest, EverySampleIsFoundByItsFingerprintAndDecodes)
{
  for (const auto& sample : allSampleMessages()) {
    EXPECT_FALSE(decoded(sample).empty()) << sample.type_name;
  }
}

TEST(MessageTypesTest, BytesOfNoProjectTypeAndShortBytesHaveNoType)
{
  const MessageTypes types(lcmtypes::messageSchema());
  const std::vector<std::uint8_t> unknown = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  EXPECT_EQ(types.typeOf(common::ByteView(unknown)), nullptr);
  const std::vector<std::uint8_t> short_bytes(sampleOn("POSE").encoded.begin(),
                                              sampleOn("POSE").encoded.begin() + 7);
  EXPECT_EQ(types.typeOf(common::ByteView(short_bytes)), nullptr);
}

TEST(MessageTypesTest, ACutMessageIsRefusedNamingTheMemberAndOffset)
{
  const MessageTypes types(lcmtypes::messageSchema());
  std::vector<std::uint8_t> bytes = sampleOn("DETECTED_OBJECTS").encoded;
  bytes.resize(bytes.size() - 1);
  const lcm_wire::StructType* type = types.typeOf(common::ByteView(bytes));
  ASSERT_NE(type, nullptr);
  const auto result = types.decode(*type, common::ByteView(bytes));
  ASSERT_TRUE(std::holds_alternative<std::string>(result));
  EXPECT_EQ(
      std::get<std::string>(result),
      "object_polygons_t.polygons[0].y claims 4 elements of at least 8 bytes at byte 65, 31 bytes left");
}

TEST(MessageFormat, APoseAsJsonIsExact)
{
  const MessageOrigin origin{"POSE", "pose_t", 1'763'800'000'200'000};
  EXPECT_EQ(jsonLine(origin, decoded(sampleOn("POSE"))),
            "{\"channel\":\"POSE\",\"type\":\"pose_t\",\"receive_utime\":1763800000200000,\"message\":{"
            "\"utime\":1763800000123456,\"position\":[10.5,-4.25,0.125],"
            "\"orientation\":[0.9238795325112867,0,0,0.3826834323650898],\"velocity\":[0.5,0.25,0],"
            "\"angular_velocity\":[0,0,0.3]}}");
}

TEST(MessageFormat, NestedStructsAsTextAreIndentedListItems)
{
  const MessageOrigin origin{"DETECTED_OBJECTS", "object_polygons_t", 1'763'800'000'123'456};
  EXPECT_EQ(textBlock(origin, decoded(sampleOn("DETECTED_OBJECTS"))),
            "--- DETECTED_OBJECTS object_polygons_t received 1763800000.123456\n"
            "  utime: 1763800000123456\n"
            "  num_polygons: 1\n"
            "  polygons:\n"
            "    - id: 7\n"
            "      kind: 1\n"
            "      num_points: 4\n"
            "      x: [3.5, 4.75, 6, 7.25]\n"
            "      y: [2, 1.25, 0.5, -0.25]\n");
}

TEST(MessageFormat, AHeartbeatsStringsAreQuotedWithJsonEscapes)
{
  const MessageOrigin origin{"HEARTBEAT", "heartbeat_t", 5};
  EXPECT_EQ(textBlock(origin, decoded(sampleOn("HEARTBEAT"))),
            "--- HEARTBEAT heartbeat_t received 0.000005\n"
            "  utime: 1763800000123456\n"
            "  process: \"planner\"\n"
            "  pid: 4242\n"
            "  sequence: 99\n"
            "  health: 1\n"
            "  message: \"packets late\"\n");
}

/// A definition with every kind of member the project's types do not all show.
constexpr const char* kTestDefinition = R"lcm(
package test;
struct every_kind_t
{
  const int8_t UNUSED = 3;
  int16_t small;
  float   ratio;
  double  values[3];
  boolean flag;
  string  label;
  int32_t size;
  byte    payload[size];
  int8_t  grid[2][2];
}
)lcm";

void putBigEndian(std::vector<std::uint8_t>& bytes, std::uint64_t value, int size)
{
  for (int shift = 8 * (size - 1); shift >= 0; shift -= 8) {
    bytes.push_back(static_cast<std::uint8_t>(value >> static_cast<unsigned>(shift)));
  }
}

TEST(MessageFormat, FloatsNonFiniteNumbersStringsBytesAndGridsInTextAndJson)
{
  const lcm_wire::Schema schema = lcm_wire::Schema::parse({kTestDefinition}, {"every_kind_t.lcm"});
  const lcm_wire::StructType& type = schema.types().front();
  std::vector<std::uint8_t> bytes;
  putBigEndian(bytes, static_cast<std::uint64_t>(fingerprintOf(schema, type)), 8);
  putBigEndian(bytes, static_cast<std::uint16_t>(-300), 2);
  float ratio = 0.1F;
  std::uint32_t ratio_bits = 0;
  std::memcpy(&ratio_bits, &ratio, 4);
  putBigEndian(bytes, ratio_bits, 4);
  for (const double value : {std::nan(""), -HUGE_VAL, 1e-7}) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, 8);
    putBigEndian(bytes, bits, 8);
  }
  bytes.push_back(1);
  const std::string label = "say \"hi\"\n";
  putBigEndian(bytes, label.size() + 1, 4);
  bytes.insert(bytes.end(), label.begin(), label.end());
  bytes.push_back(0);
  putBigEndian(bytes, 3, 4);
  bytes.insert(bytes.end(), {0x0F, 0xA0, 0x00});
  bytes.insert(bytes.end(), {0xFF, 0x02, 0x03, 0x80});

  const MessageTypes types(schema);
  ASSERT_EQ(types.typeOf(common::ByteView(bytes)), &type);
  const auto result = types.decode(type, common::ByteView(bytes));
  ASSERT_TRUE(std::holds_alternative<Members>(result)) << std::get<std::string>(result);
  const Members& members = std::get<Members>(result);
  const MessageOrigin origin{"TEST", "every_kind_t", 1'700'000'000'000'001};
  EXPECT_EQ(textBlock(origin, members),
            "--- TEST every_kind_t received 1700000000.000001\n"
            "  small: -300\n"
            "  ratio: 0.1\n"
            "  values: [nan, -inf, 1e-07]\n"
            "  flag: true\n"
            "  label: \"say \\\"hi\\\"\\n\"\n"
            "  size: 3\n"
            "  payload: 0fa000\n"
            "  grid: [[-1, 2], [3, -128]]\n");
  EXPECT_EQ(jsonLine(origin, members),
            "{\"channel\":\"TEST\",\"type\":\"every_kind_t\",\"receive_utime\":1700000000000001,\"message\":{"
            "\"small\":-300,\"ratio\":0.1,\"values\":[null,null,1e-07],\"flag\":true,\"label\":\"say "
            "\\\"hi\\\"\\n\","
            "\"size\":3,\"payload\":\"0fa000\",\"grid\":[[-1,2],[3,-128]]}}");
}

}  // namespace
}  // namespace ifar::echo
