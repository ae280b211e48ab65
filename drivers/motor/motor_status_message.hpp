#pragma once
// MotorStatus as the LCM message motor_status_t (channel MOTOR_STATUS), for the daemon that owns the
// motor client. Library ifar_motor_lcm, so ifar_motor stays free of LCM.

#include <cstdint>

#include "drivers/motor/motor_client.hpp"
#include "ifar/motor_status_t.hpp"

namespace ifar::motor {

ifar::motor_status_t toMessage(const MotorStatus& status, std::int64_t utime);

}  // namespace ifar::motor
