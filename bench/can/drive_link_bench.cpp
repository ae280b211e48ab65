// One 10 ms cycle of a running motor link: motor client update, simulated drive update, frames
// exchanged both ways (what the simulator and the headless runner spend per drive and cycle).
#include <benchmark/benchmark.h>

#include "drivers/motor/motor_client.hpp"
#include "sim/can_nodes/drive_emulator.hpp"

namespace {

void BM_MotorCycle(benchmark::State& state)
{
  ifar::motor::MotorClient client;
  ifar::sim::DriveEmulator drive;
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
