#include "drivers/can/candump_log.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace ifar::can {
namespace {

using std::chrono::microseconds;

TEST(CandumpParse, StandardFrame)
{
  const auto parsed = parseCandumpLine("(1700000000.010000) can0 201#00E8030000000000\n");
  ASSERT_EQ(parsed.status, LineStatus::kOk) << parsed.problem;
  EXPECT_EQ(parsed.interface, "can0");
  EXPECT_EQ(parsed.frame.timestamp_us, 1700000000010000);
  EXPECT_EQ(parsed.frame.id, 0x201u);
  EXPECT_EQ(parsed.frame.flags, 0);
  EXPECT_EQ(parsed.frame.dlc, 8);
  EXPECT_EQ(parsed.frame.data[1], 0xE8);
  EXPECT_EQ(parsed.frame.data[2], 0x03);
}

TEST(CandumpParse, ExtendedRemoteErrorAndEmpty)
{
  const auto extended = parseCandumpLine("(1.5) vcan0 18FF1234#0102");
  ASSERT_EQ(extended.status, LineStatus::kOk);
  EXPECT_EQ(extended.frame.timestamp_us, 1'500'000);
  EXPECT_EQ(extended.frame.id, 0x18FF1234u);
  EXPECT_TRUE(extended.frame.extended());
  EXPECT_EQ(extended.frame.dlc, 2);

  const auto remote = parseCandumpLine("(1.000000) can0 123#R3");
  ASSERT_EQ(remote.status, LineStatus::kOk);
  EXPECT_TRUE(remote.frame.remote());
  EXPECT_EQ(remote.frame.dlc, 3);

  const auto error = parseCandumpLine("(1.000000) can0 20000040#0000000000000000");
  ASSERT_EQ(error.status, LineStatus::kOk);
  EXPECT_TRUE(error.frame.error());
  EXPECT_EQ(error.frame.id, 0x40u);

  const auto empty = parseCandumpLine("(1.000000) can0 7FF#");
  ASSERT_EQ(empty.status, LineStatus::kOk);
  EXPECT_EQ(empty.frame.dlc, 0);
}

TEST(CandumpParse, ToleratesDirectionFlagDotsAndDlcSuffix)
{
  const auto flagged = parseCandumpLine("(1700000000.000001) can0 190#40E201000107002B R");
  ASSERT_EQ(flagged.status, LineStatus::kOk);
  EXPECT_EQ(flagged.frame.dlc, 8);
  const auto dotted = parseCandumpLine("(1.000000) can0 100#11.22.33");
  ASSERT_EQ(dotted.status, LineStatus::kOk);
  EXPECT_EQ(dotted.frame.dlc, 3);
  EXPECT_EQ(dotted.frame.data[2], 0x33);
  const auto suffix = parseCandumpLine("(1.000000) can0 100#1122334455667788_C");
  ASSERT_EQ(suffix.status, LineStatus::kOk);
  EXPECT_EQ(suffix.frame.dlc, 8);
}

TEST(CandumpParse, RejectsMalformedLinesWithAReason)
{
  const char* const bad_lines[] = {
      "can0 123#00",                        // no timestamp
      "(abc) can0 123#00",                  // bad timestamp
      "(1.0) can0",                         // no frame
      "(1.0) can0 123-00",                  // no '#'
      "(1.0) can0 1234#00",                 // 4-digit id
      "(1.0) can0 800#00",                  // standard id above 7FF
      "(1.0) can0 123#0",                   // odd digit count
      "(1.0) can0 123#001122334455667788",  // 9 bytes
      "(1.0) can0 123#ZZ",                  // not hex
      "(1.0) can0 123#R9",                  // remote length 9
  };
  for (const char* line : bad_lines) {
    const auto parsed = parseCandumpLine(line);
    EXPECT_EQ(parsed.status, LineStatus::kMalformed) << line;
    EXPECT_FALSE(parsed.problem.empty()) << line;
  }
  EXPECT_EQ(parseCandumpLine("(1.0) can0 123##1AABB").status, LineStatus::kUnsupportedFd);
  EXPECT_EQ(parseCandumpLine("   \n").status, LineStatus::kBlank);
}

TEST(CandumpFormat, MatchesCandumpOutput)
{
  Frame frame = makeFrame(0x201, {0x00, 0xE8, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00});
  frame.timestamp_us = 1700000000010000;
  EXPECT_EQ(formatCandumpLine(frame, "can0"), "(1700000000.010000) can0 201#00E8030000000000");
  Frame extended = makeFrame(0xABCDE, {0xDE, 0xAD});
  extended.flags = kFlagExtended;
  extended.timestamp_us = 5;
  EXPECT_EQ(formatCandumpLine(extended, "vcan0"), "(0000000000.000005) vcan0 000ABCDE#DEAD");
  Frame remote = makeFrame(0x7FF, {});
  remote.flags = kFlagRemote;
  remote.dlc = 2;
  EXPECT_EQ(formatCandumpLine(remote, "can0"), "(0000000000.000000) can0 7FF#R2");
}

TEST(CandumpLogBus, ReplaysSkippingAndCountingBadLines)
{
  auto input = std::make_unique<std::istringstream>(
      "(1.000000) can0 181#01\n"
      "garbage\n"
      "\n"
      "(2.000000) can0 201#02\n"
      "(3.000000) can0 20000040#0000000000000000\n"
      "(4.000000) can0 185#03\n");
  CandumpLogBus bus(std::move(input), nullptr);
  bus.setFilters({Filter{0x180, 0x780, false}});
  auto first = bus.receive(microseconds(0));
  ASSERT_EQ(first.status, IoStatus::kOk);
  EXPECT_EQ(first.frame.data[0], 1);
  EXPECT_EQ(first.frame.timestamp_us, 1'000'000);
  auto error = bus.receive(microseconds(0));  // 0x201 filtered out, error frame always passes
  ASSERT_EQ(error.status, IoStatus::kOk);
  EXPECT_TRUE(error.frame.error());
  EXPECT_EQ(bus.state(), BusState::kBusOff);
  EXPECT_EQ(bus.receive(microseconds(0)).frame.data[0], 3);
  EXPECT_EQ(bus.receive(microseconds(0)).status, IoStatus::kEndOfStream);
  EXPECT_EQ(bus.counters().bad_frames, 1);
  EXPECT_EQ(bus.counters().frames_received, 2);
  EXPECT_EQ(bus.counters().error_frames, 1);
}

TEST(CandumpLogBus, WriterOutputReadsBack)
{
  auto output = std::make_unique<std::ostringstream>();
  std::ostringstream* text = output.get();
  CandumpLogBus writer(nullptr, std::move(output), "can1");
  Frame frame = makeFrame(0x190, {1, 2, 3});
  frame.timestamp_us = 1700000000123456;
  ASSERT_EQ(writer.send(frame).status, IoStatus::kOk);
  EXPECT_EQ(text->str(), "(1700000000.123456) can1 190#010203\n");
  CandumpLogBus reader(std::make_unique<std::istringstream>(text->str()), nullptr);
  const auto back = reader.receive(microseconds(0));
  ASSERT_EQ(back.status, IoStatus::kOk);
  EXPECT_TRUE(sameContent(back.frame, frame));
  EXPECT_EQ(back.frame.timestamp_us, frame.timestamp_us);
}

std::string readFile(const std::string& path)
{
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

bool haveTool(const char* name)
{
  const std::string command = std::string("command -v ") + name + " >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

// can-utils' log2asc must read what our writer wrote, frame for frame.
TEST(CandumpInterop, Log2ascParsesOurLog)
{
  if (!haveTool("log2asc")) {
    GTEST_SKIP() << "can-utils log2asc not installed (apt-get install can-utils)";
  }
  const std::string log_path = std::string(IFAR_BINARY_DIR) + "/tests/can_interop_ours.log";
  const std::string asc_path = std::string(IFAR_BINARY_DIR) + "/tests/can_interop_ours.asc";
  {
    auto opened = CandumpLogBus::open("", log_path + ".tmp");
    std::remove((log_path + ".tmp").c_str());
    opened = CandumpLogBus::open("", log_path + ".tmp");
    ASSERT_NE(opened.bus, nullptr) << opened.error;
    Frame rpdo = makeFrame(0x201, {0x0F, 0x00, 0xE8, 0x03, 0x00, 0x00});
    rpdo.timestamp_us = 1700000000000000;
    Frame extended = makeFrame(0x18FF1234, {0xDE, 0xAD, 0xBE, 0xEF});
    extended.flags = kFlagExtended;
    extended.timestamp_us = 1700000000250000;
    Frame remote = makeFrame(0x123, {});
    remote.flags = kFlagRemote;
    remote.timestamp_us = 1700000000500000;
    for (const Frame& frame : {rpdo, extended, remote}) {
      ASSERT_EQ(opened.bus->send(frame).status, IoStatus::kOk);
    }
  }
  std::rename((log_path + ".tmp").c_str(), log_path.c_str());
  const std::string command = "log2asc -I " + log_path + " -O " + asc_path + " can0";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string asc = readFile(asc_path);
  EXPECT_NE(asc.find("0.000000 1  201             Rx   d 6 0F 00 E8 03 00 00"), std::string::npos) << asc;
  EXPECT_NE(asc.find("0.250000 1  18FF1234x       Rx   d 4 DE AD BE EF"), std::string::npos) << asc;
  EXPECT_NE(asc.find("0.500000 1  123             Rx   r"), std::string::npos) << asc;
}

void expectVehicleBusFrames(CanBus& bus)
{
  struct Expected {
    std::uint32_t id;
    std::uint8_t flags;
    std::uint8_t dlc;
    std::uint8_t first_byte;
  };
  const Expected expected[] = {
      {0x701, 0, 1, 0x00},           {0x000, 0, 2, 0x01}, {0x190, 0, 8, 0x40},
      {0x201, 0, 6, 0x0F},           {0x181, 0, 6, 0x37}, {0x18FF1234, kFlagExtended, 3, 0x01},
      {0x123, kFlagRemote, 2, 0x00}, {0x081, 0, 8, 0x10},
  };
  std::int64_t first_time = -1;
  int index = 0;
  for (const Expected& want : expected) {
    const auto got = bus.receive(microseconds(0));
    ASSERT_EQ(got.status, IoStatus::kOk) << "frame " << index;
    EXPECT_EQ(got.frame.id, want.id) << "frame " << index;
    EXPECT_EQ(got.frame.flags, want.flags) << "frame " << index;
    EXPECT_EQ(got.frame.dlc, want.dlc) << "frame " << index;
    EXPECT_EQ(got.frame.data[0], want.first_byte) << "frame " << index;
    if (first_time < 0)
      first_time = got.frame.timestamp_us;
    EXPECT_EQ(got.frame.timestamp_us - first_time, index * 10'000) << "frame " << index;
    ++index;
  }
  EXPECT_EQ(bus.receive(microseconds(0)).status, IoStatus::kEndOfStream);
  EXPECT_EQ(bus.counters().bad_frames, 0);
}

// A log written by can-utils (asc2log, with its trailing direction flags), checked in.
TEST(CandumpInterop, ReplaysACheckedInLogWrittenByCanUtils)
{
  auto opened =
      CandumpLogBus::open(std::string(IFAR_SOURCE_DIR) + "/tests/unit/can/data/vehicle_bus.log", "");
  ASSERT_NE(opened.bus, nullptr) << opened.error;
  expectVehicleBusFrames(*opened.bus);
}

// The same, written fresh by the installed can-utils from the .asc source.
TEST(CandumpInterop, ReplaysALogWrittenByAsc2log)
{
  if (!haveTool("asc2log")) {
    GTEST_SKIP() << "can-utils asc2log not installed (apt-get install can-utils)";
  }
  const std::string log_path = std::string(IFAR_BINARY_DIR) + "/tests/can_interop_theirs.log";
  const std::string command = "asc2log -I " + std::string(IFAR_SOURCE_DIR) +
                              "/tests/unit/can/data/vehicle_bus.asc -O " + log_path + " 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  auto opened = CandumpLogBus::open(log_path, "");
  ASSERT_NE(opened.bus, nullptr) << opened.error;
  expectVehicleBusFrames(*opened.bus);
}

}  // namespace
}  // namespace ifar::can
