#pragma once
// Runs a MotorClient and DriveEmulators in lock-step without a bus: what one sends, the others get.

#include <vector>

#include "drivers/motor/motor_client.hpp"
#include "sim/can_nodes/drive_emulator.hpp"

namespace ifar::motor {

using sim::DriveEmulator;
using sim::DriveEmulatorSettings;

struct Lockstep {
  Lockstep(MotorClient& client_under_test, DriveEmulator& drive_under_test)
      : client(client_under_test), drive(drive_under_test)
  {
  }

  MotorClient& client;
  DriveEmulator& drive;
  std::int64_t now_us = 0;
  std::vector<can::Frame> client_frames;  // everything the client sent, in order
  bool deliver_to_drive = true;

  /// One 10 ms cycle: the client (commanded `velocity` when `send_command`), then the drive.
  void step(bool send_command, std::int32_t velocity = 0)
  {
    now_us += 10'000;
    if (send_command)
      client.command(velocity, now_us);
    for (const can::Frame& frame : client.update(now_us)) {
      client_frames.push_back(frame);
      if (deliver_to_drive)
        drive.onFrame(frame, now_us);
    }
    for (const can::Frame& frame : drive.update(now_us)) {
      client.onFrame(frame, now_us);
    }
  }
  void run(int cycles, bool send_command, std::int32_t velocity = 0)
  {
    for (int index = 0; index < cycles; ++index)
      step(send_command, velocity);
  }
};

}  // namespace ifar::motor
