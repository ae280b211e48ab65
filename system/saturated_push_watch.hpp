#pragma once
// Counts pushes held at the vehicle's maximum force for too long without a decision: the failure the
// tactile monitor exists to prevent (a vehicle grinding against an unpushable object). The evaluation
// uses the simulator's true bumper force, so a monitor fooled by its own sensors shows up here.

#include <cstdint>

namespace ifar::runner {

class SaturatedPushWatch {
 public:
  /// `saturated_force_n`: the force at or above which a push is at maximum; `limit_s`: how long such a
  /// push may last without an affordance decision before it counts.
  SaturatedPushWatch(double saturated_force_n, double limit_s);

  /// The true bumper force at `now_us`; call in time order.
  void force(std::int64_t now_us, double bumper_force_n);
  /// The executive reported an affordance decision at `now_us`: the current push is decided.
  void decided(std::int64_t now_us);

  /// Spells of maximum force that lasted longer than the limit without a decision.
  int undecided() const { return undecided_; }
  /// The longest spell at maximum force without a decision so far, seconds.
  double longestUndecidedSeconds() const { return longest_s_; }

 private:
  double saturated_force_n_;
  std::int64_t limit_us_;
  std::int64_t since_us_ = -1;  // start of the current undecided spell, -1 when none
  bool counted_ = false;        // the current spell already counted
  int undecided_ = 0;
  double longest_s_ = 0.0;
};

}  // namespace ifar::runner
