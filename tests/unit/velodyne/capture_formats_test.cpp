// The real VLP-16 capture in other formats Wireshark and tcpdump write: as pcapng and as Linux cooked
// captures (SLL in pcap, SLL2 in pcapng), converted here record by record. Each gives exactly the points of
// the capture as it is, through the driver's own path (--pcap FILE --points OUT). Skipped when
// ../shared/data is absent.

#include <gtest/gtest.h>

#include <spdlog/sinks/ostream_sink.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/velodyne/capture_points.hpp"
#include "testing/temporary_directory.hpp"
#include "tests/unit/velodyne/capture_writers.hpp"

namespace ifar::velodyne {
namespace {

const std::string kCapture = std::string(IFAR_SHARED_DATA) + "/vlp16/vlp16_strongest_example.pcap";

struct Record {
  std::uint32_t seconds = 0;
  std::uint32_t microseconds = 0;
  std::vector<std::uint8_t> frame;
};

std::uint32_t little32(const std::vector<std::uint8_t>& bytes, std::size_t at)
{
  return static_cast<std::uint32_t>(bytes[at]) | (static_cast<std::uint32_t>(bytes[at + 1]) << 8) |
         (static_cast<std::uint32_t>(bytes[at + 2]) << 16) |
         (static_cast<std::uint32_t>(bytes[at + 3]) << 24);
}

/// The records of a little-endian, microsecond, Ethernet classic pcap file (the shared capture is one).
std::vector<Record> classicRecords(const std::vector<std::uint8_t>& bytes)
{
  std::vector<Record> records;
  if (bytes.size() < 24 || little32(bytes, 0) != 0xA1B2C3D4U || little32(bytes, 20) != 1) {
    return records;
  }
  for (std::size_t at = 24; at + 16 <= bytes.size();) {
    const std::uint32_t length = little32(bytes, at + 8);
    Record record{little32(bytes, at), little32(bytes, at + 4), {}};
    record.frame.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at + 16),
                        bytes.begin() + static_cast<std::ptrdiff_t>(at + 16 + length));
    records.push_back(std::move(record));
    at += 16 + length;
  }
  return records;
}

class CaptureFormats : public ::testing::Test {
 protected:
  void SetUp() override
  {
    std::ifstream file(kCapture, std::ios::binary);
    if (!file) {
      GTEST_SKIP() << "real capture not found at " << kCapture << " (shared data is not in this checkout)";
    }
    std::ostringstream text;
    text << file.rdbuf();
    const std::string contents = text.str();
    records_ = classicRecords(std::vector<std::uint8_t>(contents.begin(), contents.end()));
    ASSERT_EQ(records_.size(), 84U);
  }

  std::string write(const std::string& name, const std::string& text) const
  {
    const std::string path = (folder_.path() / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  /// The points file --points writes for `capture`, and the log.
  std::string points(const std::string& capture, const std::string& name) const
  {
    std::ostringstream log;
    auto logger =
        std::make_shared<spdlog::logger>("velodyne", std::make_shared<spdlog::sinks::ostream_sink_mt>(log));
    const std::string out = (folder_.path() / (name + ".csv")).string();
    EXPECT_EQ(writeCapturePoints(capture, out, DriverSettings{}, logger), 0) << log.str();
    EXPECT_NE(log.str().find("of 84 packets"), std::string::npos) << log.str();
    std::ifstream file(out);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
  }

  test_support::TemporaryDirectory folder_{"capture-formats"};
  std::vector<Record> records_;
};

TEST_F(CaptureFormats, PcapngAndLinuxCookedCapturesGiveTheSamePoints)
{
  PcapngWriter pcapng(1);
  PcapWriter cooked(false, false, 113);
  PcapngWriter cooked_pcapng(276);
  for (const Record& record : records_) {
    const std::uint64_t microseconds =
        static_cast<std::uint64_t>(record.seconds) * 1'000'000U + record.microseconds;
    pcapng.packet(microseconds, record.frame);
    cooked.record(record.seconds, record.microseconds, cookedFrame(record.frame, false));
    cooked_pcapng.packet(microseconds, cookedFrame(record.frame, true));
  }
  const std::string expected = points(kCapture, "pcap");
  ASSERT_GT(expected.size(), 84U * 100U);
  EXPECT_EQ(points(write("capture.pcapng", pcapng.text()), "pcapng"), expected);
  EXPECT_EQ(points(write("cooked.pcap", cooked.text()), "sll"), expected);
  EXPECT_EQ(points(write("cooked.pcapng", cooked_pcapng.text()), "sll2"), expected);
}

}  // namespace
}  // namespace ifar::velodyne
