#pragma once
// Random numbers that are the same for a seed on every platform: the 64-bit Mersenne Twister's output is
// fixed by the standard, the std:: distributions are not, so the mapping to ranges is done here.

#include <cstdint>
#include <random>

namespace ifar::sim {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [low, high).
  double uniform(double low, double high)
  {
    const double unit = static_cast<double>(engine_() >> 11) * (1.0 / 9007199254740992.0);  // 2^-53
    return low + (high - low) * unit;
  }

  /// Uniform integer in [low, high] (high >= low).
  int integer(int low, int high)
  {
    const auto span = static_cast<std::uint64_t>(high - low) + 1;
    return low + static_cast<int>(engine_() % span);
  }

  bool chance(double probability) { return uniform(0.0, 1.0) < probability; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace ifar::sim
