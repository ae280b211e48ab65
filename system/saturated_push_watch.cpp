#include "system/saturated_push_watch.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::runner {

SaturatedPushWatch::SaturatedPushWatch(double saturated_force_n, double limit_s)
    : saturated_force_n_(saturated_force_n), limit_us_(std::llround(limit_s * 1e6))
{
}

void SaturatedPushWatch::force(std::int64_t now_us, double bumper_force_n)
{
  if (!(bumper_force_n >= saturated_force_n_)) {
    since_us_ = -1;
    counted_ = false;
    return;
  }
  if (since_us_ < 0) {
    since_us_ = now_us;
    return;
  }
  const std::int64_t held_us = now_us - since_us_;
  longest_s_ = std::max(longest_s_, static_cast<double>(held_us) * 1e-6);
  if (held_us > limit_us_ && !counted_) {
    ++undecided_;
    counted_ = true;
  }
}

void SaturatedPushWatch::decided(std::int64_t now_us)
{
  // A push still at maximum after the decision starts a new spell: the decision must change something.
  if (since_us_ >= 0) {
    since_us_ = now_us;
    counted_ = false;
  }
}

}  // namespace ifar::runner
