#pragma once
// Pi and degree conversions: one definition for every component.

namespace ifar::geometry {

inline constexpr double kPi = 3.14159265358979323846;

constexpr double radiansFromDegrees(double degrees)
{
  return degrees * kPi / 180.0;
}

constexpr double degreesFromRadians(double radians)
{
  return radians * 180.0 / kPi;
}

}  // namespace ifar::geometry
