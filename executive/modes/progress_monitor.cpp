#include "executive/modes/progress_monitor.hpp"

#include <cmath>

namespace ifar::executive {

void ProgressMonitor::startGoal()
{
  best_remaining_m_.reset();
  stuck_us_ = 0;
  last_us_.reset();
  visited_.clear();
}

bool ProgressMonitor::newGround(const geometry::Point& position)
{
  if (!(settings_.new_ground_m > 0.0) || !position.allFinite()) {
    return false;
  }
  const auto square = [this](double value) {
    return static_cast<std::int64_t>(std::floor(value / settings_.new_ground_m));
  };
  return visited_.emplace(square(position.x()), square(position.y())).second;
}

bool ProgressMonitor::update(std::int64_t now_us, const geometry::Point& position, double remaining_m,
                             bool counting)
{
  const std::int64_t elapsed_us = last_us_ && now_us > *last_us_ ? now_us - *last_us_ : 0;
  last_us_ = now_us;
  if (!(settings_.timeout_s > 0.0) || !std::isfinite(remaining_m)) {
    return false;
  }
  const bool explored = newGround(position);
  if (!best_remaining_m_ || remaining_m < *best_remaining_m_ - settings_.margin_m || explored) {
    if (!best_remaining_m_ || remaining_m < *best_remaining_m_) {
      best_remaining_m_ = remaining_m;
    }
    stuck_us_ = 0;
    return false;
  }
  if (counting) {
    stuck_us_ += elapsed_us;
  }
  if (static_cast<double>(stuck_us_) * 1e-6 < settings_.timeout_s) {
    return false;
  }
  // Escalated: what the loop does next is judged afresh from where the vehicle is now.
  stuck_us_ = 0;
  best_remaining_m_ = remaining_m;
  return true;
}

}  // namespace ifar::executive
