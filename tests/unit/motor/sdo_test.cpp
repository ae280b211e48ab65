#include "drivers/motor/sdo.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace ifar::motor {
namespace {

std::vector<std::uint8_t> bytes(const can::Frame& frame)
{
  return std::vector<std::uint8_t>(frame.data.begin(), frame.data.begin() + frame.dlc);
}

TEST(Sdo, ExpeditedDownloadBytesBySize)
{
  // Consumer heartbeat of node 127, 150 ms, into node 2: 0x1016:01 = 0x007F0096.
  const can::Frame four = encodeSdoDownload(2, {0x1016, 0x01, 0x007F0096, 4});
  EXPECT_EQ(four.id, 0x602u);
  EXPECT_EQ(bytes(four), (std::vector<std::uint8_t>{0x23, 0x16, 0x10, 0x01, 0x96, 0x00, 0x7F, 0x00}));
  EXPECT_EQ(bytes(encodeSdoDownload(1, {0x1400, 0x05, 100, 2})),
            (std::vector<std::uint8_t>{0x2B, 0x00, 0x14, 0x05, 0x64, 0x00, 0x00, 0x00}));
  EXPECT_EQ(bytes(encodeSdoDownload(1, {0x6060, 0x00, 3, 1})),
            (std::vector<std::uint8_t>{0x2F, 0x60, 0x60, 0x00, 0x03, 0x00, 0x00, 0x00}));
  // Bytes beyond the size are sent as 0 whatever the value held.
  EXPECT_EQ(bytes(encodeSdoDownload(1, {0x6007, 0x00, 0xFFFF0003, 2})),
            (std::vector<std::uint8_t>{0x2B, 0x07, 0x60, 0x00, 0x03, 0x00, 0x00, 0x00}));
  EXPECT_EQ(encodeSdoDownload(1, {0x2000, 0x00, 0x123456, 3}).data[0], 0x27);
}

TEST(Sdo, RequestsDecodeAsTheServerSeesThem)
{
  const auto download = decodeSdoRequest(encodeSdoDownload(5, {0x607F, 0x00, 9066, 4}), 5);
  ASSERT_TRUE(download);
  EXPECT_EQ(download->kind, SdoRequest::Kind::kDownload);
  EXPECT_EQ(download->write, (SdoWrite{0x607F, 0x00, 9066, 4}));
  const auto two =
      decodeSdoRequest(can::makeFrame(0x605, {0x2B, 0x07, 0x60, 0x00, 0x03, 0x00, 0xAA, 0xBB}), 5);
  ASSERT_TRUE(two);
  EXPECT_EQ(two->write, (SdoWrite{0x6007, 0x00, 3, 2}));  // unused bytes ignored
  // The reserved bit 4 set (0x33): still a 4-byte expedited download (found by fuzz_canopen_decoders).
  const auto reserved = decodeSdoRequest(can::makeFrame(0x605, {0x33, 0x7F, 0x60, 0x00, 1, 2, 3, 4}), 5);
  ASSERT_TRUE(reserved);
  EXPECT_EQ(reserved->write, (SdoWrite{0x607F, 0x00, 0x04030201, 4}));
  const auto abort = decodeSdoRequest(encodeSdoAbort(0x605, 0x1016, 1, kAbortTimedOut), 5);
  ASSERT_TRUE(abort);
  EXPECT_EQ(abort->kind, SdoRequest::Kind::kAbort);
  EXPECT_EQ(abort->abort_code, kAbortTimedOut);
  // An upload request (0x40) and a segmented download (0x21) are not served here.
  EXPECT_EQ(decodeSdoRequest(can::makeFrame(0x605, {0x40, 0x41, 0x60, 0, 0, 0, 0, 0}), 5)->kind,
            SdoRequest::Kind::kUnsupported);
  EXPECT_EQ(decodeSdoRequest(can::makeFrame(0x605, {0x21, 0x41, 0x60, 0, 8, 0, 0, 0}), 5)->kind,
            SdoRequest::Kind::kUnsupported);
  EXPECT_FALSE(decodeSdoRequest(can::makeFrame(0x605, {0x23, 0x41, 0x60}), 5));  // too short
  EXPECT_FALSE(decodeSdoRequest(encodeSdoDownload(6, {0x607F, 0, 1, 4}), 5));    // another node's
}

TEST(Sdo, AnswersBytesAndDecoding)
{
  const can::Frame confirmed = encodeSdoDownloadConfirmed(1, 0x1016, 0x01);
  EXPECT_EQ(confirmed.id, 0x581u);
  EXPECT_EQ(bytes(confirmed), (std::vector<std::uint8_t>{0x60, 0x16, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00}));
  const auto decoded = decodeSdoAnswer(confirmed, 1);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->kind, SdoAnswer::Kind::kDownloadConfirmed);
  EXPECT_EQ(decoded->index, 0x1016);
  EXPECT_EQ(decoded->subindex, 0x01);

  const can::Frame abort = encodeSdoAbort(0x581, 0x607F, 0x00, kAbortValueRange);
  EXPECT_EQ(bytes(abort), (std::vector<std::uint8_t>{0x80, 0x7F, 0x60, 0x00, 0x30, 0x00, 0x09, 0x06}));
  const auto aborted = decodeSdoAnswer(abort, 1);
  ASSERT_TRUE(aborted);
  EXPECT_EQ(aborted->kind, SdoAnswer::Kind::kAbort);
  EXPECT_EQ(aborted->abort_code, 0x06090030u);
  EXPECT_STREQ(sdoAbortText(aborted->abort_code), "invalid value for parameter (value range exceeded)");
  // An upload answer (0x43) is no download answer.
  EXPECT_FALSE(decodeSdoAnswer(can::makeFrame(0x581, {0x43, 0x00, 0x10, 0, 0x92, 0x01, 0x02, 0x00}), 1));
}

}  // namespace
}  // namespace ifar::motor
