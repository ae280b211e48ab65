// Throughput of the CAN codecs the drivers run per frame: candump parsing and formatting (log replay
// and recording), the force frame decoder, and one motor client + drive emulator cycle.
#include <benchmark/benchmark.h>

#include <string>

#include "drivers/can/candump_log.hpp"
#include "drivers/force_sensor/force_frame.hpp"
#include "drivers/motor/drive_emulator.hpp"
#include "drivers/motor/motor_client.hpp"

namespace {

void BM_CandumpParse(benchmark::State& state)
{
  const std::string line = "(1700000000.010000) can0 201#0F00E80300000000";
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(ifar::can::parseCandumpLine(line));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CandumpParse);

void BM_CandumpFormat(benchmark::State& state)
{
  ifar::can::Frame frame = ifar::can::makeFrame(0x201, {0x0F, 0x00, 0xE8, 0x03, 0x00, 0x00, 0x00, 0x00});
  frame.timestamp_us = 1700000000010000;
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(ifar::can::formatCandumpLine(frame, "can0"));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CandumpFormat);

void BM_ForceFrameDecode(benchmark::State& state)
{
  const ifar::can::Frame frame = ifar::force_sensor::encodeForceFrame({123.456, 7, false, false});
  for ([[maybe_unused]] auto _ : state) {
    benchmark::DoNotOptimize(ifar::force_sensor::decodeForceFrame(frame));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ForceFrameDecode);

// One 10 ms cycle of a running link: client update, drive update, frames exchanged both ways.
void BM_MotorCycle(benchmark::State& state)
{
  ifar::motor::MotorClient client;
  ifar::motor::DriveEmulator drive;
  std::int64_t now = 0;
  for ([[maybe_unused]] auto _ : state) {
    now += 10'000;
    client.command(1000, now);
    for (const auto& frame : client.update(now))
      drive.onFrame(frame, now);
    for (const auto& frame : drive.update(now))
      client.onFrame(frame, now);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MotorCycle);

}  // namespace
