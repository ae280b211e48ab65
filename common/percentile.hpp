#pragma once
// Nearest-rank percentiles: the value at rank ceil(p/100 * n) of the sorted values, so every percentile
// is one of the measured values (no interpolation between two runs).

#include <vector>

namespace ifar::common {

/// Nearest-rank percentile (p in 0..100) of unsorted values; NaN when empty.
double nearestRankPercentile(std::vector<double> values, double p);

}  // namespace ifar::common
