#include "bench/scenarios/sim_time_budget.hpp"

#include <sstream>

namespace ifar::scenarios {

std::string SimTimeBudget::describe() const
{
  std::ostringstream text;
  text << base_s << " s + " << per_metre_s << " s/m";
  return text.str();
}

}  // namespace ifar::scenarios
