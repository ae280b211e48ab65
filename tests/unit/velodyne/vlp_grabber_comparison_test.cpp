// Checks the decoder against an independent implementation: PCL's pcl::VLPGrabber on the real capture.
//
// How VLPGrabber delivers points (PCL 1.13, io/src/vlp_grabber.cpp and hdl_grabber.cpp):
// - from a pcap file it replays UDP payloads of 1206 bytes in real time in a reader thread;
// - the sweep callback fires when a point's azimuth is below the previous point's, with the points
//   gathered so far; the points after the last wrap are never delivered. On this capture (234 degrees
//   to a little past 360) that is exactly one sweep: the first, partial revolution.
// - points with distance 0 become NaN and are dropped; intensity is the reflectivity byte;
// - frame: x = d cos(elevation) sin(azimuth), y = d cos(elevation) cos(azimuth) (y forward, x right),
//   where ours is x forward, y left (x = d cos(el) cos(az), y = -d cos(el) sin(az)); so
//   pcl.x = -ours.y and pcl.y = ours.x;
// - the second firing's azimuth is the block's plus half the step between the first two blocks of the
//   packet, truncated to whole 0.01 degree (the value goes through an integer parameter).
// Our decoder has an interpolation option reproducing the last convention, so points can be compared
// like with like to 1 mm; with our default (half the packet's mean block step) the second-firing
// points differ by up to about 0.02 degree in azimuth, which is checked separately.

#include <gtest/gtest.h>

#include <pcl/io/vlp_grabber.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "drivers/velodyne/packet_decoder.hpp"
#include "drivers/velodyne/pcap_reader.hpp"
#include "drivers/velodyne/revolution_assembler.hpp"

namespace ifar::velodyne {
namespace {

const std::string kCapture = std::string(IFAR_SHARED_DATA) + "/vlp16/vlp16_strongest_example.pcap";

std::vector<pcl::PointCloud<pcl::PointXYZI>> pclSweeps()
{
  std::mutex mutex;
  std::vector<pcl::PointCloud<pcl::PointXYZI>> sweeps;
  pcl::VLPGrabber grabber(kCapture);
  std::function<void(const pcl::PointCloud<pcl::PointXYZI>::ConstPtr&)> on_sweep =
      [&](const pcl::PointCloud<pcl::PointXYZI>::ConstPtr& cloud) {
        const std::lock_guard<std::mutex> lock(mutex);
        sweeps.push_back(*cloud);
      };
  grabber.registerCallback(on_sweep);
  grabber.start();
  // isRunning() stays true after a pcap replay ends in PCL 1.13, so wait for the first sweep and then
  // for longer than the whole capture lasts (84 packets, 0.11 s) before stopping.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  auto have_sweep = [&] {
    const std::lock_guard<std::mutex> lock(mutex);
    return !sweeps.empty();
  };
  while (!have_sweep() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  grabber.stop();
  const std::lock_guard<std::mutex> lock(mutex);
  return sweeps;
}

/// Our first revolutions; `second_firing` gets, in point order, whether each point is from a block's
/// second firing (read from the packet-relative time offset before the assembler re-bases it).
std::vector<Revolution> ourRevolutions(AzimuthInterpolation interpolation,
                                       std::vector<bool>* second_firing = nullptr)
{
  std::vector<Revolution> revolutions;
  RevolutionAssembler assembler([&](const Revolution& revolution) { revolutions.push_back(revolution); });
  PcapReader reader = PcapReader::open(kCapture);
  EXPECT_EQ(reader.error(), PcapError::kNone);
  DecoderOptions options;
  options.interpolation = interpolation;
  UdpDatagram datagram;
  std::vector<Point> points;
  while (reader.next(datagram) == PcapRecord::kUdpDatagram) {
    points.clear();
    EXPECT_EQ(decodePacket(datagram.payload, points, options).info.status, PacketStatus::kOk);
    for (const Point& point : points) {
      if (second_firing != nullptr) {
        second_firing->push_back(std::fmod(point.time_offset_us, kBlockDurationMicroseconds) >=
                                 kFiringSequenceMicroseconds - 1.0);
      }
    }
    assembler.add(points, datagram.capture_time_us);
  }
  return revolutions;  // the partial revolution after the last wrap stays pending, as in PCL
}

class VelodyneVlpGrabberComparison : public ::testing::Test {
 protected:
  void SetUp() override
  {
    if (!std::ifstream(kCapture).good()) {
      GTEST_SKIP() << "real capture not found at " << kCapture << " (shared data is not in this checkout)";
    }
  }
};

TEST_F(VelodyneVlpGrabberComparison, SamePointsWithinOneMillimetre)
{
  const auto sweeps = pclSweeps();
  const auto revolutions = ourRevolutions(AzimuthInterpolation::kVlpGrabber);
  ASSERT_EQ(sweeps.size(), 1U);
  ASSERT_EQ(revolutions.size(), 1U);
  const auto& reference = sweeps[0];
  const auto& ours = revolutions[0].points;
  ASSERT_EQ(ours.size(), reference.size());
  ASSERT_GT(ours.size(), 9000U);  // 9895 points in the first, partial revolution
  double worst = 0.0;
  for (std::size_t index = 0; index < ours.size(); ++index) {
    const pcl::PointXYZI& expected = reference[index];
    const Point& point = ours[index];
    const double error = std::hypot(-point.y - expected.x, point.x - expected.y, point.z - expected.z);
    worst = std::max(worst, error);
    ASSERT_LT(error, 0.001) << "point " << index << " laser " << int(point.laser) << " azimuth "
                            << point.azimuth_degrees;
    ASSERT_EQ(static_cast<float>(point.reflectivity), expected.intensity) << "point " << index;
  }
  RecordProperty("worst_error_m", std::to_string(worst));
}

TEST_F(VelodyneVlpGrabberComparison, DefaultInterpolationDiffersOnlyInSecondFiringAzimuth)
{
  const auto sweeps = pclSweeps();
  std::vector<bool> second_firing_flags;
  const auto revolutions = ourRevolutions(AzimuthInterpolation::kPacketMeanStep, &second_firing_flags);
  ASSERT_EQ(sweeps.size(), 1U);
  ASSERT_EQ(revolutions.size(), 1U);
  const auto& reference = sweeps[0];
  const auto& ours = revolutions[0].points;
  ASSERT_EQ(ours.size(), reference.size());
  constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
  for (std::size_t index = 0; index < ours.size(); ++index) {
    const pcl::PointXYZI& expected = reference[index];
    const Point& point = ours[index];
    // Range and height do not depend on the azimuth: same to 1 mm.
    const double reference_range = std::hypot(expected.x, expected.y, expected.z);
    ASSERT_NEAR(point.distance, reference_range, 0.001) << "point " << index;
    ASSERT_NEAR(point.z, expected.z, 0.001) << "point " << index;
    // Horizontal position: same on the first firing, within 0.02 degree of arc on the second.
    const double horizontal_error = std::hypot(-point.y - expected.x, point.x - expected.y);
    const double horizontal_range = std::hypot(expected.x, expected.y);
    const bool second_firing = second_firing_flags[index];
    const double allowed = second_firing ? horizontal_range * 0.02 * kRadiansPerDegree + 0.001 : 0.001;
    ASSERT_LT(horizontal_error, allowed) << "point " << index << (second_firing ? " (second firing)" : "");
  }
}

}  // namespace
}  // namespace ifar::velodyne
