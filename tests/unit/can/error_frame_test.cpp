#include "drivers/can/error_frame.hpp"

#include <gtest/gtest.h>

namespace ifar::can {
namespace {

TEST(ErrorFrame, BusOffWins)
{
  const Frame frame = makeErrorFrame(kErrorBusOff | kErrorController, kControllerTxPassive);
  EXPECT_EQ(stateAfterErrorFrame(frame, BusState::kActive), BusState::kBusOff);
  EXPECT_EQ(describeErrorFrame(frame), "controller tx-passive, bus-off");
}

TEST(ErrorFrame, ControllerStatusGivesWarningAndPassive)
{
  EXPECT_EQ(stateAfterErrorFrame(makeErrorFrame(kErrorController, kControllerRxWarning), BusState::kActive),
            BusState::kWarning);
  EXPECT_EQ(stateAfterErrorFrame(makeErrorFrame(kErrorController, kControllerTxPassive), BusState::kWarning),
            BusState::kPassive);
  EXPECT_EQ(stateAfterErrorFrame(makeErrorFrame(kErrorController, kControllerActive), BusState::kPassive),
            BusState::kActive);
}

TEST(ErrorFrame, RestartReturnsToActive)
{
  EXPECT_EQ(stateAfterErrorFrame(makeErrorFrame(kErrorRestarted), BusState::kBusOff), BusState::kActive);
}

TEST(ErrorFrame, ProtocolErrorAloneSaysNothingAboutState)
{
  EXPECT_FALSE(stateAfterErrorFrame(makeErrorFrame(kErrorProtocol | kErrorNoAck), BusState::kActive));
  EXPECT_EQ(describeErrorFrame(makeErrorFrame(kErrorProtocol | kErrorNoAck)), "protocol, no-ack");
}

TEST(ErrorFrame, DataFrameIsNotAnErrorFrame)
{
  EXPECT_FALSE(stateAfterErrorFrame(makeFrame(kErrorBusOff, {0, 0}), BusState::kActive));
}

}  // namespace
}  // namespace ifar::can
