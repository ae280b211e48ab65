// Throughput of the CAN codecs the drivers run per frame: candump parsing and formatting (log replay
// and recording) and the force frame decoder. (One motor client + simulated drive cycle:
// sim/can_nodes/bench.)
#include <benchmark/benchmark.h>

#include <string>

#include "drivers/can/candump_log.hpp"
#include "drivers/force_sensor/force_frame.hpp"

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

}  // namespace
