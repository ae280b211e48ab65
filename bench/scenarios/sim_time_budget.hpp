#pragma once
// How long (simulated seconds) a driven run may take before it counts as a failure: a base plus a
// per-metre allowance on a length, capped. One definition for the runner's stop (given Task::budgetLength)
// and for the tables that report the same runs against a stricter budget (on the exact optimum).

#include <algorithm>
#include <string>

namespace ifar::scenarios {

struct SimTimeBudget {
  double base_s = 60.0;
  double per_metre_s = 4.0;
  double max_s = 1800.0;

  double seconds(double optimal_m) const { return std::min(max_s, base_s + per_metre_s * optimal_m); }
  /// "60 s + 2 s/m" (the cap left out: it is the same for every budget in one run).
  std::string describe() const;
};

}  // namespace ifar::scenarios
