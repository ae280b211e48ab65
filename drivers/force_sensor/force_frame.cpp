#include "drivers/force_sensor/force_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ifar::force_sensor {
namespace {

std::uint8_t checksum(const std::uint8_t* bytes)
{
  unsigned sum = 0;
  for (int index = 0; index < 7; ++index) {
    sum += bytes[index];
  }
  return static_cast<std::uint8_t>(sum & 0xFF);
}

}  // namespace

const char* toString(DecodeStatus status)
{
  switch (status) {
    case DecodeStatus::kOk:
      return "ok";
    case DecodeStatus::kWrongId:
      return "wrong id";
    case DecodeStatus::kNotDataFrame:
      return "not a data frame";
    case DecodeStatus::kWrongLength:
      return "wrong length";
    case DecodeStatus::kBadChecksum:
      return "bad checksum";
  }
  return "unknown";
}

can::Frame encodeForceFrame(const ForceReading& reading, std::uint32_t frame_id)
{
  can::Frame frame;
  frame.id = frame_id & can::kStandardIdMask;
  frame.dlc = kFrameLength;
  const double counts =
      std::isfinite(reading.force_newtons) ? std::round(reading.force_newtons / kNewtonsPerCount) : 0.0;
  const auto value = static_cast<std::int32_t>(
      std::clamp(counts, static_cast<double>(std::numeric_limits<std::int32_t>::min()),
                 static_cast<double>(std::numeric_limits<std::int32_t>::max())));
  can::writeU32Le(frame.data.data(), static_cast<std::uint32_t>(value));
  frame.data[4] = static_cast<std::uint8_t>((reading.overload ? kStatusOverload : 0) |
                                            (reading.fault ? kStatusFault : 0));
  frame.data[5] = reading.counter;
  frame.data[6] = 0;
  frame.data[7] = checksum(frame.data.data());
  return frame;
}

DecodeResult decodeForceFrame(const can::Frame& frame, std::uint32_t frame_id)
{
  DecodeResult result;
  if (frame.error() || frame.remote()) {
    result.status = DecodeStatus::kNotDataFrame;
    return result;
  }
  if (frame.extended() || frame.id != frame_id) {
    result.status = DecodeStatus::kWrongId;
    return result;
  }
  if (frame.dlc != kFrameLength) {
    result.status = DecodeStatus::kWrongLength;
    return result;
  }
  if (checksum(frame.data.data()) != frame.data[7]) {
    result.status = DecodeStatus::kBadChecksum;
    return result;
  }
  const auto counts = static_cast<std::int32_t>(can::readU32Le(frame.data.data()));
  result.reading.force_newtons = static_cast<double>(counts) * kNewtonsPerCount;
  result.reading.overload = (frame.data[4] & kStatusOverload) != 0;
  result.reading.fault = (frame.data[4] & kStatusFault) != 0;
  result.reading.counter = frame.data[5];
  return result;
}

can::Frame ForceSensorEmulator::nextFrame(double force_newtons)
{
  ForceReading reading;
  const double force = std::isfinite(force_newtons) ? std::max(force_newtons, 0.0) : 0.0;
  reading.overload = force > range_newtons_;
  reading.force_newtons = std::min(force, range_newtons_);
  reading.fault = fault_;
  reading.counter = counter_;
  if (!counter_frozen_) {
    counter_ = static_cast<std::uint8_t>(counter_ + 1);
  }
  return encodeForceFrame(reading, frame_id_);
}

}  // namespace ifar::force_sensor
