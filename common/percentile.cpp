#include "common/percentile.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::common {

double nearestRankPercentile(std::vector<double> values, double p)
{
  if (values.empty()) {
    return NAN;
  }
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(p / 100.0 * static_cast<double>(values.size()));
  const std::size_t index = static_cast<std::size_t>(std::max(1.0, rank)) - 1;
  return values[std::min(index, values.size() - 1)];
}

}  // namespace ifar::common
