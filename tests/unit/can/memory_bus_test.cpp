#include "drivers/can/memory_bus.hpp"

#include <gtest/gtest.h>

#include "drivers/can/error_frame.hpp"

namespace ifar::can {
namespace {

using std::chrono::microseconds;

TEST(MemoryBus, DeliversToOthersNotToSender)
{
  auto network = MemoryNetwork::create();
  auto first = network->attach("a");
  auto second = network->attach("b");
  auto third = network->attach("c");
  ASSERT_EQ(first->send(makeFrame(0x123, {0xAA})).status, IoStatus::kOk);
  const auto received = second->receive(microseconds(0));
  ASSERT_EQ(received.status, IoStatus::kOk);
  EXPECT_EQ(received.frame.id, 0x123u);
  EXPECT_EQ(received.frame.data[0], 0xAA);
  EXPECT_EQ(third->receive(microseconds(0)).status, IoStatus::kOk);
  EXPECT_EQ(first->receive(microseconds(0)).status, IoStatus::kTimeout);
  EXPECT_EQ(first->counters().frames_sent, 1);
  EXPECT_EQ(second->counters().frames_received, 1);
}

TEST(MemoryBus, FiltersByIdAndMask)
{
  auto pair = makeMemoryBusPair();
  pair.second->setFilters({Filter{0x180, 0x780, false}});  // every TPDO1 0x180..0x1FF
  pair.first->send(makeFrame(0x181, {1}));
  pair.first->send(makeFrame(0x201, {2}));
  pair.first->send(makeFrame(0x1FF, {3}));
  Frame extended = makeFrame(0x181, {4});
  extended.flags = kFlagExtended;
  pair.first->send(extended);
  EXPECT_EQ(pair.second->receive(microseconds(0)).frame.data[0], 1);
  EXPECT_EQ(pair.second->receive(microseconds(0)).frame.data[0], 3);
  EXPECT_EQ(pair.second->receive(microseconds(0)).status, IoStatus::kTimeout);
}

TEST(MemoryBus, ErrorFramesSetBusStateAndBusOffRefusesSends)
{
  auto network = MemoryNetwork::create();
  auto endpoint = network->attach("a");
  network->injectErrorFrame(makeErrorFrame(kErrorController, kControllerTxPassive));
  auto received = endpoint->receive(microseconds(0));
  ASSERT_EQ(received.status, IoStatus::kOk);
  EXPECT_TRUE(received.frame.error());
  EXPECT_EQ(endpoint->state(), BusState::kPassive);
  network->injectErrorFrame(makeErrorFrame(kErrorBusOff));
  endpoint->receive(microseconds(0));
  EXPECT_EQ(endpoint->state(), BusState::kBusOff);
  const auto sent = endpoint->send(makeFrame(0x1, {}));
  EXPECT_EQ(sent.status, IoStatus::kError);
  EXPECT_NE(sent.error.find("bus-off"), std::string::npos);
  EXPECT_EQ(endpoint->counters().write_errors, 1);
  EXPECT_EQ(endpoint->counters().error_frames, 2);
}

TEST(MemoryBus, ReceiveWaitsForTheTimeout)
{
  auto pair = makeMemoryBusPair();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(pair.first->receive(microseconds(20'000)).status, IoStatus::kTimeout);
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(19));
}

}  // namespace
}  // namespace ifar::can
