#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench/scenarios/driven_outcome.hpp"
#include "bench/scenarios/generalization_tables.hpp"

namespace ifar::scenarios {
namespace {

TEST(DrivenOutcome, NoPathInFarModeIsCorrectOnlyWherePushingIsRequired)
{
  const std::string no_path = "stopped: no path; planner: no path: goal enclosed";
  EXPECT_EQ(drivenStatus(false, no_path, true, NAN), "no_path_pushing_required");
  EXPECT_EQ(drivenStatus(false, no_path, true, 12.0), "no_path");
  EXPECT_EQ(drivenStatus(false, no_path, false, NAN), "no_path");
  EXPECT_EQ(drivenStatus(false, "timeout after 100 s of simulated time (following)", true, 12.0),
            "time_limit");
  EXPECT_EQ(drivenStatus(false, "stopped: collision", false, 12.0), "failed");
  EXPECT_EQ(drivenStatus(true, "arrived", true, NAN), "arrived");
  EXPECT_TRUE(correctOutcome("no_path_pushing_required"));
  EXPECT_FALSE(correctOutcome("no_path"));
}

ResultRow drivenRow(const std::string& planner, const std::string& task, bool arrived, double without_pushing,
                    const std::string& status)
{
  ResultRow row;
  row.table = "system";
  row.planner = planner;
  row.kind = "namosim";
  row.world = "two_rooms";
  row.task = task;
  row.success = arrived;
  row.optimal = 10.0;
  row.achievable = 10.0;
  row.without_pushing = without_pushing;
  row.length = arrived ? 11.0 : 3.0;
  row.status = status;
  row.reason = arrived ? "" : "stopped: no path; planner: no path";
  return row;
}

TEST(GeneralizationTargets, FarModesNoPathOnAGoalWithAWayRoundIsAMiss)
{
  std::vector<ResultRow> rows{drivenRow("far", "g0", false, NAN, "no_path_pushing_required"),
                              drivenRow("ours", "g0", true, NAN, "arrived")};
  std::string targets = generalizationTargets(rows);
  EXPECT_NE(targets.find("reports no path only where pushing is required | 0 no path"), std::string::npos)
      << targets;
  EXPECT_NE(targets.find("1 of 1 goals"), std::string::npos) << targets;
  // Ours arrived on the one reachable goal with SPL 10/11.
  EXPECT_NE(targets.find("1/1, SPL 0.909 | met"), std::string::npos) << targets;

  rows.push_back(drivenRow("far", "g1", false, 14.0, "no_path"));
  rows.push_back(drivenRow("ours", "g1", false, 14.0, "no_path"));
  targets = generalizationTargets(rows);
  EXPECT_NE(targets.find("1 no path with a way that never pushes"), std::string::npos) << targets;
  EXPECT_NE(targets.find("1/2, SPL 0.455 | missed"), std::string::npos) << targets;
  const std::string table = tableGeneralization(rows);
  EXPECT_NE(table.find("| two_rooms | g1 |"), std::string::npos) << table;
}

}  // namespace
}  // namespace ifar::scenarios
