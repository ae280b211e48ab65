#pragma once
// When a daemon's inputs last arrived, for its heartbeat: "no VELODYNE_PACKET for 3.2 s". No LCM here; the
// daemon calls arrived() from its subscriptions and problem() at each beat.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ifar::common {

class InputSilence {
 public:
  /// Inputs silent for more than `limit_s` seconds count; `start_us` stands in for the last arrival of an
  /// input that has not arrived yet (a daemon just started is not yet missing anything).
  InputSilence(std::int64_t start_us, double limit_s);

  /// Watches one more input; returns its index for arrived().
  std::size_t watch(std::string name);
  void arrived(std::size_t input, std::int64_t now_us);

  /// Each silent input, "no NAME for 3.2 s" (with " (none since start)" when it never arrived), joined by
  /// ", "; empty when none is.
  std::string problem(std::int64_t now_us) const;

 private:
  struct Input {
    std::string name;
    std::int64_t last_us = 0;
    bool ever = false;
  };
  std::int64_t start_us_;
  std::int64_t limit_us_;
  std::vector<Input> inputs_;
};

/// `text` with every duration in seconds ("3.2 s") replaced by "N s": the same problem as it goes on, for
/// telling a change of what is wrong from the clock running (a log line or a readiness summary on change).
std::string withoutDurations(const std::string& text);

}  // namespace ifar::common
