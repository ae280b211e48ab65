// One suite run against every CanBus implementation that can form a two-endpoint link in-process
// (SocketCAN runs the same checks against a real kernel in tests/socketcan).
#include <gtest/gtest.h>

#include <memory>

#include "drivers/can/lcm_bridge_bus.hpp"
#include "drivers/can/memory_bus.hpp"

namespace ifar::can {
namespace {

using std::chrono::microseconds;

struct Link {
  std::shared_ptr<void> keep_alive;  // whatever the endpoints need to outlive them
  std::unique_ptr<CanBus> first;
  std::unique_ptr<CanBus> second;
};

struct MemoryLink {
  static Link make()
  {
    auto pair = makeMemoryBusPair();
    return Link{nullptr, std::move(pair.first), std::move(pair.second)};
  }
};

struct LcmLink {
  static Link make()
  {
    auto lcm = std::make_shared<lcm::LCM>("memq://");
    Link link;
    link.first = std::make_unique<LcmBridgeBus>(*lcm, "CAN_CONTRACT");
    link.second = std::make_unique<LcmBridgeBus>(*lcm, "CAN_CONTRACT");
    link.keep_alive = lcm;
    return link;
  }
};

template <typename Factory>
class CanBusContract : public ::testing::Test {
 protected:
  // Endpoints are declared after keep_alive in Link, so they are destroyed first.
  Link link = Factory::make();
};

using Implementations = ::testing::Types<MemoryLink, LcmLink>;
TYPED_TEST_SUITE(CanBusContract, Implementations);

TYPED_TEST(CanBusContract, DeliversContentToThePeerOnly)
{
  Frame frame = makeFrame(0x18FF1234, {1, 2, 3, 4, 5, 6, 7, 8});
  frame.flags = kFlagExtended;
  ASSERT_EQ(this->link.first->send(frame).status, IoStatus::kOk);
  const auto received = this->link.second->receive(microseconds(100'000));
  ASSERT_EQ(received.status, IoStatus::kOk);
  EXPECT_TRUE(sameContent(received.frame, frame));
  EXPECT_EQ(this->link.first->receive(microseconds(5'000)).status, IoStatus::kTimeout);
  EXPECT_EQ(this->link.first->counters().frames_sent, 1);
  EXPECT_EQ(this->link.second->counters().frames_received, 1);
}

TYPED_TEST(CanBusContract, FiltersOnTheReceiver)
{
  this->link.second->setFilters({Filter{0x700, 0x780, false}});  // heartbeats only
  this->link.first->send(makeFrame(0x181, {1}));
  this->link.first->send(makeFrame(0x701, {5}));
  const auto received = this->link.second->receive(microseconds(100'000));
  ASSERT_EQ(received.status, IoStatus::kOk);
  EXPECT_EQ(received.frame.id, 0x701u);
  EXPECT_EQ(this->link.second->receive(microseconds(5'000)).status, IoStatus::kTimeout);
  this->link.second->setFilters({});
  this->link.first->send(makeFrame(0x181, {1}));
  EXPECT_EQ(this->link.second->receive(microseconds(100'000)).status, IoStatus::kOk);
}

TYPED_TEST(CanBusContract, TimeoutWithNothingSent)
{
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(this->link.second->receive(microseconds(20'000)).status, IoStatus::kTimeout);
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(15));
}

TYPED_TEST(CanBusContract, RefusesAnOverlongFrame)
{
  Frame frame = makeFrame(0x100, {});
  frame.dlc = 9;
  const auto sent = this->link.first->send(frame);
  EXPECT_EQ(sent.status, IoStatus::kError);
  EXPECT_FALSE(sent.error.empty());
  EXPECT_EQ(this->link.first->counters().write_errors, 1);
}

}  // namespace
}  // namespace ifar::can
