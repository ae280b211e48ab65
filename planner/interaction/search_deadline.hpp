#pragma once
// When a search must stop: a time budget counted from when the query started, and a most number of
// expansions. Searches poll it; running out is an expected outcome they report as a status.

#include <chrono>
#include <cstddef>
#include <limits>

namespace ifar::interaction {

class SearchDeadline {
 public:
  using Clock = std::chrono::steady_clock;

  SearchDeadline(Clock::time_point started, double time_budget_s, std::size_t max_expansions)
      : started_(started), time_budget_s_(time_budget_s), max_expansions_(max_expansions)
  {
  }
  /// Neither time nor expansions run out; elapsedSeconds() still counts from `started`.
  static SearchDeadline unlimited(Clock::time_point started)
  {
    return SearchDeadline(started, std::numeric_limits<double>::infinity(),
                          std::numeric_limits<std::size_t>::max());
  }

  double elapsedSeconds() const { return std::chrono::duration<double>(Clock::now() - started_).count(); }
  bool outOfTime() const { return elapsedSeconds() > time_budget_s_; }
  bool outOfExpansions(std::size_t expansions) const { return expansions >= max_expansions_; }

 private:
  Clock::time_point started_;
  double time_budget_s_;
  std::size_t max_expansions_;
};

}  // namespace ifar::interaction
