#include "drivers/velodyne/packet_decoder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/unit/velodyne/packet_builder.hpp"

namespace ifar::velodyne {
namespace {

using testing::PacketBuilder;

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

std::vector<Point> decodeOk(const std::vector<std::uint8_t>& bytes, const DecoderOptions& options = {})
{
  std::vector<Point> points;
  const DecodeResult result = decodePacket(common::ByteView(bytes), points, options);
  EXPECT_EQ(result.info.status, PacketStatus::kOk) << toString(result.info.status);
  EXPECT_EQ(result.points_added, points.size());
  return points;
}

TEST(VelodyneDecoder, LaserZeroAtAzimuthZeroPointsForwardAndDown)
{
  const auto points = decodeOk(PacketBuilder().azimuthRamp(0, 40).ret(0, 0, 5000, 77).bytes());
  ASSERT_EQ(points.size(), 1U);
  const Point& point = points[0];
  EXPECT_FLOAT_EQ(point.distance, 10.0F);
  EXPECT_NEAR(point.x, 10.0 * std::cos(15.0 * kDegrees), 1e-5);  // 9.659258 m
  EXPECT_NEAR(point.y, 0.0, 1e-6);
  EXPECT_NEAR(point.z, -10.0 * std::sin(15.0 * kDegrees), 1e-5);  // -2.588190 m
  EXPECT_FLOAT_EQ(point.azimuth_degrees, 0.0F);
  EXPECT_EQ(point.reflectivity, 77);
  EXPECT_EQ(point.laser, 0);
  EXPECT_EQ(point.ring, 0);
  EXPECT_EQ(point.return_index, 0);
  EXPECT_EQ(point.return_type, ReturnType::kStrongest);
  EXPECT_FLOAT_EQ(point.time_offset_us, 0.0F);
}

TEST(VelodyneDecoder, AzimuthNinetyDegreesIsToTheRight)
{
  // Laser 1 (+1 degree), 5 m, block 0 at 90.00 degrees: clockwise rotation puts it on -y.
  const auto points = decodeOk(PacketBuilder().azimuthRamp(9000, 40).ret(0, 1, 2500, 10).bytes());
  ASSERT_EQ(points.size(), 1U);
  EXPECT_NEAR(points[0].x, 0.0, 1e-6);
  EXPECT_NEAR(points[0].y, -5.0 * std::cos(1.0 * kDegrees), 1e-5);  // -4.999239 m
  EXPECT_NEAR(points[0].z, 5.0 * std::sin(1.0 * kDegrees), 1e-6);   // 0.087262 m
  EXPECT_EQ(points[0].ring, 8);
  EXPECT_EQ(points[0].laser, 1);
}

TEST(VelodyneDecoder, ExactDistanceUnitsAndRingOrder)
{
  PacketBuilder builder;
  builder.azimuthRamp(18000, 40);
  for (std::size_t laser = 0; laser < 16; ++laser) {
    builder.ret(2, laser, static_cast<std::uint16_t>(1 + laser * 1000),
                static_cast<std::uint8_t>(laser + 100));
  }
  const auto points = decodeOk(builder.bytes());
  ASSERT_EQ(points.size(), 16U);
  const std::uint8_t expected_rings[16] = {0, 8, 1, 9, 2, 10, 3, 11, 4, 12, 5, 13, 6, 14, 7, 15};
  const double elevations[16] = {-15, 1, -13, 3, -11, 5, -9, 7, -7, 9, -5, 11, -3, 13, -1, 15};
  for (std::size_t laser = 0; laser < 16; ++laser) {
    const double distance = (1 + laser * 1000) * 0.002;
    EXPECT_FLOAT_EQ(points[laser].distance, static_cast<float>(distance));
    EXPECT_EQ(points[laser].ring, expected_rings[laser]);
    EXPECT_EQ(points[laser].reflectivity, laser + 100);
    EXPECT_FLOAT_EQ(points[laser].azimuth_degrees, 180.8F);
    // Azimuth 180.8 degrees: behind the sensor, slightly to the left.
    const double horizontal = distance * std::cos(elevations[laser] * kDegrees);
    EXPECT_NEAR(points[laser].x, horizontal * std::cos(180.8 * kDegrees), 2e-6);
    EXPECT_NEAR(points[laser].y, -horizontal * std::sin(180.8 * kDegrees), 2e-6);
    EXPECT_NEAR(points[laser].z, distance * std::sin(elevations[laser] * kDegrees), 2e-6);
  }
}

TEST(VelodyneDecoder, SecondFiringIsHalfTheMeanBlockStepLater)
{
  // Blocks 40 hundredths apart except a jittery block 5: mean step over the packet stays 40.
  PacketBuilder builder;
  builder.azimuthRamp(1000, 40).azimuth(5, 1202).ret(3, 16, 1000, 1).ret(3, 0, 1000, 1);
  const auto points = decodeOk(builder.bytes());
  ASSERT_EQ(points.size(), 2U);
  EXPECT_FLOAT_EQ(points[0].azimuth_degrees, 11.20F);  // block 3 firing 1: 1000 + 3 * 40
  EXPECT_FLOAT_EQ(points[1].azimuth_degrees, 11.40F);  // firing 2: + 40 / 2
}

TEST(VelodyneDecoder, VlpGrabberInterpolationUsesFirstStepTruncated)
{
  PacketBuilder builder;
  builder.azimuthRamp(1000, 40).azimuth(1, 1039).ret(3, 16, 1000, 1);
  DecoderOptions options;
  options.interpolation = AzimuthInterpolation::kVlpGrabber;
  const auto points = decodeOk(builder.bytes(), options);
  ASSERT_EQ(points.size(), 1U);
  // First step 39 -> half 19.5 -> 1120 + 19.5 = 1139.5 truncated to 1139.
  EXPECT_FLOAT_EQ(points[0].azimuth_degrees, 11.39F);
}

TEST(VelodyneDecoder, SecondFiringWrapsAt360Degrees)
{
  // Block 0 at 359.90 degrees, 0.40 degree steps: its second firing lands at 360.10 -> 0.10 degrees.
  const auto points =
      decodeOk(PacketBuilder().azimuthRamp(35990, 40).ret(0, 16, 1000, 1).ret(1, 0, 1000, 1).bytes());
  ASSERT_EQ(points.size(), 2U);
  EXPECT_NEAR(points[0].azimuth_degrees, 0.10F, 1e-4);
  EXPECT_FLOAT_EQ(points[1].azimuth_degrees, 0.30F);  // block 1 raw azimuth 30
  EXPECT_GT(points[0].x, 1.9F);
  EXPECT_LT(points[0].y, 0.0F);  // just clockwise of forward: to the right
}

TEST(VelodyneDecoder, SecondFiringExactlyAt360IsZero)
{
  const auto points = decodeOk(PacketBuilder().azimuthRamp(35980, 40).ret(0, 16, 1000, 1).bytes());
  ASSERT_EQ(points.size(), 1U);
  EXPECT_FLOAT_EQ(points[0].azimuth_degrees, 0.0F);
}

TEST(VelodyneDecoder, TimeOffsetsFollowTheFiringTable)
{
  const auto points = decodeOk(PacketBuilder().azimuthRamp(0, 40).allReturns(1000, 1).bytes());
  ASSERT_EQ(points.size(), 384U);
  // Block 3, firing 2, laser 5 is point 3 * 32 + 16 + 5.
  EXPECT_NEAR(points[3 * 32 + 16 + 5].time_offset_us, 7 * 55.296 + 5 * 2.304, 1e-3);  // 398.592 us
  EXPECT_NEAR(points[1].time_offset_us, 2.304, 1e-4);
  EXPECT_NEAR(points[16].time_offset_us, 55.296, 1e-4);
  EXPECT_NEAR(points[383].time_offset_us, 23 * 55.296 + 15 * 2.304, 1e-3);  // 1306.368 us
}

TEST(VelodyneDecoder, DualReturnPairsShareFiringTimesAndAzimuths)
{
  PacketBuilder builder;
  builder.mode(0x39);
  // Block pairs share an azimuth: 100, 100, 140, 140, ...
  for (std::size_t block = 0; block < 12; ++block) {
    builder.azimuth(block, static_cast<std::uint16_t>(100 + (block / 2) * 40));
  }
  builder.ret(2, 3, 1500, 20).ret(3, 3, 2000, 200).ret(2, 19, 1500, 20).ret(3, 19, 2000, 200);
  const auto points = decodeOk(builder.bytes());
  ASSERT_EQ(points.size(), 4U);
  // Block 2: last return, block 3: strongest return of the same firings (pair 1).
  EXPECT_EQ(points[0].return_type, ReturnType::kLast);
  EXPECT_EQ(points[0].return_index, 0);
  EXPECT_FLOAT_EQ(points[0].distance, 3.0F);
  EXPECT_EQ(points[2].return_type, ReturnType::kStrongest);
  EXPECT_EQ(points[2].return_index, 1);
  EXPECT_FLOAT_EQ(points[2].distance, 4.0F);
  EXPECT_NEAR(points[0].time_offset_us, 2 * 55.296 + 3 * 2.304, 1e-3);
  EXPECT_NEAR(points[2].time_offset_us, 2 * 55.296 + 3 * 2.304, 1e-3);
  EXPECT_NEAR(points[1].time_offset_us, 3 * 55.296 + 3 * 2.304, 1e-3);
  EXPECT_FLOAT_EQ(points[0].azimuth_degrees, 1.40F);
  EXPECT_FLOAT_EQ(points[2].azimuth_degrees, 1.40F);
  // Second firing: half the pair step (40) later.
  EXPECT_FLOAT_EQ(points[1].azimuth_degrees, 1.60F);
  EXPECT_FLOAT_EQ(points[3].azimuth_degrees, 1.60F);
}

TEST(VelodyneDecoder, LastReturnModeMarksPoints)
{
  const auto points = decodeOk(PacketBuilder().mode(0x38).azimuthRamp(0, 40).ret(0, 0, 10, 1).bytes());
  ASSERT_EQ(points.size(), 1U);
  EXPECT_EQ(points[0].return_type, ReturnType::kLast);
  EXPECT_EQ(points[0].return_index, 0);
}

TEST(VelodyneDecoder, ZeroDistanceIsNoReturnUnlessKept)
{
  const auto bytes = PacketBuilder().azimuthRamp(0, 40).ret(0, 0, 1, 1).bytes();
  EXPECT_EQ(decodeOk(bytes).size(), 1U);
  DecoderOptions options;
  options.keep_no_return = true;
  const auto points = decodeOk(bytes, options);
  ASSERT_EQ(points.size(), 384U);
  EXPECT_FLOAT_EQ(points[1].distance, 0.0F);
  EXPECT_FLOAT_EQ(points[1].x, 0.0F);
}

TEST(VelodyneDecoder, ReportsDeviceTimestampAndAppends)
{
  std::vector<Point> points(3);
  const auto bytes = PacketBuilder().azimuthRamp(0, 40).ret(0, 0, 1, 1).timestamp(3'599'999'999U).bytes();
  const DecodeResult result = decodePacket(common::ByteView(bytes), points);
  EXPECT_EQ(result.info.device_time_past_hour, 3'599'999'999U);
  EXPECT_EQ(result.info.return_mode, ReturnMode::kStrongest);
  EXPECT_EQ(result.points_added, 1U);
  EXPECT_EQ(points.size(), 4U);
}

struct BadPacketCase {
  const char* name;
  std::vector<std::uint8_t> bytes;
  PacketStatus expected;
};

std::vector<std::uint8_t> resized(std::size_t size)
{
  auto bytes = PacketBuilder().allReturns(100, 1).bytes();
  bytes.resize(size, 0);
  return bytes;
}

TEST(VelodyneDecoder, EachBadInputHasItsStatusAndAddsNothing)
{
  const std::vector<BadPacketCase> cases = {
      {"empty", {}, PacketStatus::kWrongSize},
      {"truncated", resized(1205), PacketStatus::kWrongSize},
      {"oversized", resized(1207), PacketStatus::kWrongSize},
      {"position packet", resized(512), PacketStatus::kWrongSize},
      {"marker first byte", PacketBuilder().byte(0, 0xFE).bytes(), PacketStatus::kBadBlockMarker},
      {"marker of block 11", PacketBuilder().byte(1101, 0xDD).bytes(), PacketStatus::kBadBlockMarker},
      {"azimuth 36000", PacketBuilder().azimuth(5, 36000).bytes(), PacketStatus::kAzimuthOutOfRange},
      {"azimuth 65535", PacketBuilder().azimuth(11, 65535).bytes(), PacketStatus::kAzimuthOutOfRange},
      {"HDL-32E product", PacketBuilder().product(0x21).bytes(), PacketStatus::kUnknownProduct},
      {"VLP-32C product", PacketBuilder().product(0x28).bytes(), PacketStatus::kUnknownProduct},
      {"mode 0x36", PacketBuilder().mode(0x36).bytes(), PacketStatus::kUnknownReturnMode},
      {"mode 0x00", PacketBuilder().mode(0x00).bytes(), PacketStatus::kUnknownReturnMode},
      // The first problem in check order wins.
      {"marker and product", PacketBuilder().byte(200, 0).product(0).bytes(), PacketStatus::kBadBlockMarker},
  };
  for (const auto& bad : cases) {
    std::vector<Point> points;
    const DecodeResult result = decodePacket(common::ByteView(bad.bytes), points);
    EXPECT_EQ(result.info.status, bad.expected) << bad.name << ": " << toString(result.info.status);
    EXPECT_EQ(result.points_added, 0U) << bad.name;
    EXPECT_TRUE(points.empty()) << bad.name;
  }
}

TEST(VelodyneDecoder, AConfiguredVlp16DecodesAnyProductByteAndSaysSo)
{
  DecoderOptions vlp16;
  vlp16.sensor_model = SensorModel::kVlp16;
  const auto genuine = PacketBuilder().azimuthRamp(100, 20).allReturns(1000, 7).bytes();
  std::vector<Point> expected;
  const DecodeResult plain = decodePacket(common::ByteView(genuine), expected, vlp16);
  ASSERT_EQ(plain.info.status, PacketStatus::kOk);
  EXPECT_FALSE(plain.info.product_overridden);  // 0x22 needs no override
  for (const std::uint8_t product : {0x21, 0x28, 0x00, 0xFF}) {
    auto bytes = genuine;
    bytes[1205] = product;
    std::vector<Point> points;
    const DecodeResult result = decodePacket(common::ByteView(bytes), points, vlp16);
    ASSERT_EQ(result.info.status, PacketStatus::kOk) << int(product);
    EXPECT_TRUE(result.info.product_overridden) << int(product);
    EXPECT_EQ(result.info.product_byte, product);
    EXPECT_EQ(points.size(), expected.size());
  }
  // The other checks still hold: only the label is overridden.
  std::vector<Point> points;
  EXPECT_EQ(decodePacket(common::ByteView(PacketBuilder().product(0x21).mode(0x36).bytes()), points, vlp16)
                .info.status,
            PacketStatus::kUnknownReturnMode);
  EXPECT_EQ(decodePacket(common::ByteView(PacketBuilder().product(0x21).byte(0, 0).bytes()), points, vlp16)
                .info.status,
            PacketStatus::kBadBlockMarker);
}

TEST(VelodyneDecoder, ARefusedProductIsNamedWithTheOneExpected)
{
  const PacketInfo info = inspectPacket(common::ByteView(PacketBuilder().product(0x28).bytes()));
  ASSERT_EQ(info.status, PacketStatus::kUnknownProduct);
  EXPECT_EQ(describeProblem(info),
            "product byte 0x28 (expected 0x22, VLP-16); set sensor_model: VLP-16 to decode it anyway");
  EXPECT_EQ(describeProblem(inspectPacket(common::ByteView(PacketBuilder().mode(0).bytes()))),
            "unknown return mode");
  EXPECT_EQ(overriddenProductWarning(0x28, SensorModel::kVlp16),
            "data packets carry product byte 0x28 (VLP-32C), not 0x22: decoding them as VLP-16 because "
            "sensor_model says so; if the sensor is not a VLP-16 its points are wrong");
  const std::string unknown = "data packets carry product byte 0x99, not 0x22:";  // no model to name
  EXPECT_EQ(overriddenProductWarning(0x99, SensorModel::kVlp16).substr(0, unknown.size()), unknown);
}

TEST(VelodyneDecoder, EachOverriddenProductByteIsNoticedOnce)
{
  ProductOverrideNotices notices;
  PacketInfo info;
  info.status = PacketStatus::kOk;
  info.product_byte = 0x21;
  EXPECT_FALSE(notices.firstOverride(info));  // not overridden: nothing to say
  info.product_overridden = true;
  EXPECT_TRUE(notices.firstOverride(info));
  EXPECT_FALSE(notices.firstOverride(info));
  info.product_byte = 0x28;
  EXPECT_TRUE(notices.firstOverride(info));
  EXPECT_FALSE(notices.firstOverride(info));
}

TEST(VelodyneDecoder, StatusNamesAreReadable)
{
  EXPECT_STREQ(toString(PacketStatus::kOk), "ok");
  EXPECT_STREQ(toString(PacketStatus::kWrongSize), "wrong size");
  EXPECT_STREQ(toString(PacketStatus::kBadBlockMarker), "bad block marker");
  EXPECT_STREQ(toString(PacketStatus::kAzimuthOutOfRange), "azimuth out of range");
  EXPECT_STREQ(toString(PacketStatus::kUnknownProduct), "unknown product");
  EXPECT_STREQ(toString(PacketStatus::kUnknownReturnMode), "unknown return mode");
}

}  // namespace
}  // namespace ifar::velodyne
