// The issue 8 target check: the issue's Office is the Willow Garage plan plus the generated offices, so
// the check pools their rows ("office+willow") beside the per-kind lines.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bench/scenarios/result_row.hpp"
#include "bench/scenarios/tables.hpp"

namespace ifar::scenarios {
namespace {

ResultRow row(const std::string& table, const std::string& planner, const std::string& kind, bool success,
              double length, double optimal, double ms, const std::string& task = "t0")
{
  ResultRow result;
  result.table = table;
  result.planner = planner;
  result.kind = kind;
  result.world = kind + "-1";
  result.task = task;
  result.success = success;
  result.length = length;
  result.optimal = optimal;
  result.ms = ms;
  result.status = success ? "solved" : "no_path";
  return result;
}

/// The line of `text` that starts with `start`, or "" when there is none.
std::string lineStartingWith(const std::string& text, const std::string& start)
{
  const std::size_t at = text.find("\n" + start);
  if (at == std::string::npos) {
    return "";
  }
  return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST(TargetCheck, PoolsTheGeneratedOfficesWithWillowAsTheIssuesOffice)
{
  std::vector<ResultRow> rows;
  // Generated offices: grid A* 10 ms, ours 0.1 ms on each of three tasks.
  for (const std::string task : {"t0", "t1", "t2"}) {
    rows.push_back(row("search", "grid_astar", "office", true, 90.0, 90.0, 10.0, task));
    rows.push_back(row("search", "ours", "office", true, 90.0, 90.0, 0.1, task));
  }
  // Willow: grid A* solves one task in 0.6 ms and fails two (no path); ours takes 0.02 ms on that one and
  // 0.1 ms on the other two.
  rows.push_back(row("search", "grid_astar", "willow", true, 45.0, 45.0, 0.6, "t0"));
  rows.push_back(row("search", "grid_astar", "willow", false, NAN, 45.0, 0.5, "t1"));
  rows.push_back(row("search", "grid_astar", "willow", false, NAN, 45.0, 0.5, "t2"));
  rows.push_back(row("search", "ours", "willow", true, 45.0, 45.0, 0.02, "t0"));
  rows.push_back(row("search", "ours", "willow", true, 45.0, 45.0, 0.1, "t1"));
  rows.push_back(row("search", "ours", "willow", true, 45.0, 45.0, 0.1, "t2"));
  const std::string check = targetCheck(rows);
  // The medians compare grid A*'s one task with ours' three; per task, on the one both solve, it is 30x.
  EXPECT_EQ(lineStartingWith(check, "| ours >= 10x faster than grid_astar (willow, median) | 6.0x"),
            "| ours >= 10x faster than grid_astar (willow, median) | 6.0x (0.600 vs 0.100 ms; per task, on "
            "the 1 both solve: median 30.0x) | missed |")
      << check;
  EXPECT_NE(lineStartingWith(check,
                             "| ours >= 10x faster than grid_astar (office, median) | 100.0x (10.00 vs "
                             "0.100 ms; per task, on the 3 both solve: median 100.0x) | met"),
            "")
      << check;
  // Pooled: grid A*'s median over its four successful queries is 10 ms, ours over six is 0.1 ms.
  EXPECT_NE(lineStartingWith(check, "| ours >= 10x faster than grid_astar (office+willow, median) | 100.0x")
                .find("met"),
            std::string::npos)
      << check;
}

TEST(TargetCheck, PooledOfficeSplAndTravelCountEveryDrivenTaskOfBothKinds)
{
  std::vector<ResultRow> rows;
  rows.push_back(row("system", "ours", "office", true, 100.0, 90.0, 1.0));  // SPL 0.9
  rows.push_back(row("system", "ours", "willow", false, 60.0, 45.0, 1.0));  // SPL 0
  rows.push_back(row("system", "far", "office", true, 200.0, 90.0, 1.0));
  rows.push_back(row("system", "far", "willow", false, 40.0, 45.0, 1.0));
  const std::string check = targetCheck(rows);
  EXPECT_NE(lineStartingWith(check, "| SPL office >= 0.90 (driven) | 0.900, success 1/1 | met").size(), 0U)
      << check;
  EXPECT_NE(
      lineStartingWith(check, "| SPL office+willow >= 0.90 (driven) | 0.450, success 1/2 | missed by 0.450")
          .size(),
      0U)
      << check;
  // 160 m against 240 m; the optimal lengths, 135 m, would be 43.8 % less than FAR mode's drive.
  EXPECT_NE(lineStartingWith(check,
                             "| ours travels >= 40% less than FAR mode (office+willow) | 33.3% (the "
                             "optimal lengths: 43.8% less) | missed")
                .size(),
            0U)
      << check;
  EXPECT_NE(lineStartingWith(check,
                             "| ours travels >= 40% less than FAR mode (office) | 50.0% (the optimal "
                             "lengths: 55.0% less) | met")
                .size(),
            0U)
      << check;
}

TEST(TargetCheck, PlannedSplIsCheckedBesideDrivenSpl)
{
  // The paper's Table II scores paths on the known map; the runner's rows score what was driven.
  std::vector<ResultRow> rows;
  rows.push_back(row("search", "ours", "office", true, 90.0, 90.0, 0.1));   // SPL 1
  rows.push_back(row("search", "ours", "willow", false, NAN, 45.0, 0.1));   // SPL 0
  rows.push_back(row("system", "ours", "office", true, 180.0, 90.0, 1.0));  // SPL 0.5
  const std::string check = targetCheck(rows);
  EXPECT_NE(lineStartingWith(check, "| SPL office >= 0.90 (planned) | 1.000, success 1/1 | met").size(), 0U)
      << check;
  EXPECT_NE(
      lineStartingWith(check, "| SPL office+willow >= 0.90 (planned) | 0.500, success 1/2 | missed by 0.400")
          .size(),
      0U)
      << check;
  EXPECT_NE(
      lineStartingWith(check, "| SPL office >= 0.90 (driven) | 0.500, success 1/1 | missed by 0.400").size(),
      0U)
      << check;
  // Without runner rows only the planned lines are there.
  rows.pop_back();
  EXPECT_EQ(targetCheck(rows).find("(driven)"), std::string::npos) << targetCheck(rows);
}

TEST(TargetCheck, SplNamesWhatFollowingTheAchievablePathsWouldScore)
{
  // A heavy crate across the shortest way: the achievable path is 180 m for the 120 m optimum, so even a
  // vehicle that knew the map scores (1 + 2/3) / 2 = 0.833 here, below the 0.97 target.
  ResultRow first = row("system", "ours", "tunnel", true, 100.0, 100.0, 1.0, "t0");
  first.achievable = 100.0;
  ResultRow second = row("system", "ours", "tunnel", true, 240.0, 120.0, 1.0, "t1");
  second.achievable = 180.0;
  // The planned paths push the crate with the prior mass: shorter than the achievable one.
  ResultRow planned_first = row("search", "ours", "tunnel", true, 100.0, 100.0, 0.1, "t0");
  planned_first.achievable = 100.0;
  ResultRow planned_second = row("search", "ours", "tunnel", true, 120.0, 120.0, 0.1, "t1");
  planned_second.achievable = 180.0;
  std::string check = targetCheck({first, second, planned_first, planned_second});
  EXPECT_NE(
      lineStartingWith(check,
                       "| SPL tunnel >= 0.97 (driven) | 0.750, success 2/2; the achievable paths: 0.833 "
                       "| missed by 0.220, beyond any vehicle in these worlds |")
          .size(),
      0U)
      << check;
  EXPECT_NE(lineStartingWith(check,
                             "| SPL tunnel >= 0.97 (planned) | 1.000, success 2/2; the achievable paths: "
                             "0.833 | met |")
                .size(),
            0U)
      << check;
  // With the crate light enough to push the world allows the target, and the verdict is the planner's.
  second.achievable = 120.0;
  check = targetCheck({first, second});
  EXPECT_NE(
      lineStartingWith(check,
                       "| SPL tunnel >= 0.97 (driven) | 0.750, success 2/2; the achievable paths: 1.000 "
                       "| missed by 0.220 |")
          .size(),
      0U)
      << check;
}

TEST(TableTwo, DrivenSplIsAlsoGivenAgainstWhatTheWorldAllows)
{
  ResultRow driven = row("system", "ours", "office", true, 100.0, 90.0, 1.0);
  driven.achievable = 95.0;  // a heavy box across the shortest way: 5 m round it
  const std::string table = tableTwoSpl({driven});
  EXPECT_NE(table.find("| ours (driven) | not run | not run | 0.900 (1/1) | not run | not run |"),
            std::string::npos)
      << table;
  EXPECT_NE(
      table.find("| ours (driven, vs achievable) | not run | not run | 0.950 (1/1) | not run | not run |"),
      std::string::npos)
      << table;
}

TEST(TableTwo, DrivenSplIsAlsoGivenForTheArrivalsWithinAStricterBudget)
{
  // Two office runs of ours, 90 m optima: one arrived at 200 s (within 60 s + 2 s/m = 240 s), one at
  // 300 s (within the runner's 60 s + 4 s/m = 420 s only).
  ResultRow early = row("system", "ours", "office", true, 100.0, 90.0, 1.0);
  early.sim_time_s = 200.0;
  ResultRow late = row("system", "ours", "office", true, 90.0, 90.0, 1.0);
  late.task = "t1";
  late.sim_time_s = 300.0;
  SimTimeBudget stricter;
  stricter.per_metre_s = 2.0;
  EXPECT_DOUBLE_EQ(stricter.seconds(90.0), 240.0);
  const std::string table = tableTwoSpl({early, late}, stricter);
  EXPECT_NE(table.find("| ours (driven) | not run | not run | 0.950 (2/2) | not run | not run |"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("| ours (driven, arrived within 60 s + 2 s/m) | not run | not run | 0.450 (1/2) | not "
                       "run | not run |"),
            std::string::npos)
      << table;
  EXPECT_EQ(tableTwoSpl({early, late}).find("arrived within"), std::string::npos);
}

TEST(PlannerFrames, PerKindMedianOfMediansWorstP99LongestFrameAndInteraction)
{
  std::vector<ResultRow> rows;
  const auto driven = [&](const std::string& task, double median, double p99, double longest,
                          double interaction) {
    ResultRow result = row("system", "ours", "tunnel", true, 100.0, 90.0, 1000.0, task);
    result.status = "arrived";
    result.frame_median_ms = median;
    result.frame_p99_ms = p99;
    result.frame_max_ms = longest;
    result.interaction_max_ms = interaction;
    rows.push_back(result);
  };
  driven("t0", 7.0, 12.0, 20.0, 3.0);
  driven("t1", 9.0, 36.0, 166.3, 140.9);
  driven("t2", 8.0, 10.0, 11.0, 0.5);
  ResultRow not_run = row("system", "ours", "tunnel", false, NAN, 90.0, NAN, "t3");
  not_run.status = "runner_unavailable";
  rows.push_back(not_run);
  const std::string table = tablePlannerFrames(rows, 2);
  EXPECT_NE(table.find("wall ms (2 runs at once"), std::string::npos) << table;
  EXPECT_NE(tablePlannerFrames(rows, 1).find("wall ms (one run at a time"), std::string::npos);
  const std::string ours = lineStartingWith(table, "| ours |");
  EXPECT_NE(ours.find(" 8.0 / 36.0 / 166.3 (140.9) |"), std::string::npos) << table;
  EXPECT_NE(lineStartingWith(table, "| far |").find("| - |"), std::string::npos) << table;
}

/// A driven row of ours in the office under `sensing`.
ResultRow drivenOffice(const std::string& sensing, const std::string& task, bool arrived, double length,
                       double p99_ms, int undecided)
{
  ResultRow result = row("system", "ours", "office", arrived, length, 90.0, 1000.0, task);
  result.status = arrived ? "arrived" : "failed";
  result.sensing = sensing;
  result.frame_median_ms = p99_ms / 2.0;
  result.frame_p99_ms = p99_ms;
  result.frame_max_ms = p99_ms;
  result.undecided_saturated_pushes = undecided;
  return result;
}

TEST(SensingProfiles, FieldRowsAreTabledApartAndCheckedAgainstIdeal)
{
  const std::vector<ResultRow> rows{
      drivenOffice("ideal", "t0", true, 100.0, 9.0, 0), drivenOffice("ideal", "t1", true, 90.0, 9.0, 0),
      drivenOffice("field", "t0", true, 110.0, 18.0, 0), drivenOffice("field", "t1", true, 95.0, 24.0, 1)};
  const std::string table = tableTwoSpl(rows);
  // Ideal: (0.9 + 1.0) / 2; field: (90/110 + 90/95) / 2.
  EXPECT_NE(lineStartingWith(table, "| ours (driven) |").find(" 0.950 (2/2) |"), std::string::npos) << table;
  EXPECT_NE(lineStartingWith(table, "| ours (driven, field) |").find(" 0.883 (2/2) |"), std::string::npos)
      << table;
  EXPECT_NE(lineStartingWith(tableThreeSystem(rows), "| ours (field) |").find(" 205.0 |"), std::string::npos)
      << tableThreeSystem(rows);
  const std::string targets = targetCheck(rows);
  // 0.883 < 0.95 x 0.950; the worst field p99 is 24 ms; one push was left undecided.
  EXPECT_NE(targets.find(
                "| ours driven SPL under field >= 0.95 x ideal, the same arrival rate (office) | 0.883 (2/2) "
                "vs 0.950 (2/2) | missed |"),
            std::string::npos)
      << targets;
  EXPECT_NE(targets.find("| planner frame p99 <= 20 ms under field (office, worst run) | 24.0 ms | missed |"),
            std::string::npos)
      << targets;
  EXPECT_NE(targets.find("(4 driven runs) | 1 | missed |"), std::string::npos) << targets;
}

TEST(SensingProfiles, FieldWithinTheTargetsIsMet)
{
  const std::vector<ResultRow> rows{drivenOffice("ideal", "t0", true, 100.0, 9.0, 0),
                                    drivenOffice("field", "t0", true, 102.0, 19.0, 0)};
  const std::string targets = targetCheck(rows);
  EXPECT_NE(targets.find("(office) | 0.882 (1/1) vs 0.900 (1/1) | met |"), std::string::npos) << targets;
  EXPECT_NE(targets.find("(office, worst run) | 19.0 ms | met |"), std::string::npos) << targets;
  EXPECT_NE(targets.find("(2 driven runs) | 0 | met |"), std::string::npos) << targets;
}

TEST(SensingProfiles, FieldDrawsCompareByArrivalRate)
{
  // One exact ideal drive of the task, three field drives of it with different sensing seeds.
  std::vector<ResultRow> rows{drivenOffice("ideal", "t0", true, 100.0, 9.0, 0)};
  for (const int seed : {1, 2, 3}) {
    rows.push_back(drivenOffice("field", "t0", true, 100.0, 9.0, 0));
    rows.back().sensing_seed = seed;
  }
  EXPECT_NE(targetCheck(rows).find("(office, 3 sensing seeds) | 0.900 (3/3) vs 0.900 (1/1) | met |"),
            std::string::npos)
      << targetCheck(rows);
  // Two of three field draws arrive: a lower arrival rate misses though the SPL of the arrivals is the same.
  rows.back() = drivenOffice("field", "t0", false, NAN, 9.0, 0);
  rows.back().sensing_seed = 3;
  EXPECT_NE(targetCheck(rows).find("(office, 3 sensing seeds) | 0.600 (2/3) vs 0.900 (1/1) | missed |"),
            std::string::npos)
      << targetCheck(rows);
}

}  // namespace
}  // namespace ifar::scenarios

namespace ifar::scenarios {
namespace {

TEST(LossTable, MeanBucketsPerPlannerAndProfileAndTheLargestGap)
{
  std::vector<ResultRow> rows;
  const auto driven = [&rows](const std::string& planner, const std::string& sensing, double length,
                              double excess, const runner::LossBuckets& losses) {
    ResultRow result = row("system", planner, "office", true, length, 80.0, 1000.0);
    result.sensing = sensing;
    result.excess_m = excess;
    result.losses = losses;
    rows.push_back(result);
  };
  driven("far", "ideal", 120.0, 40.0, {10.0, 0.0, 5.0, 20.0, 5.0, 0.0});
  driven("far", "ideal", 100.0, 20.0, {0.0, 0.0, 5.0, 10.0, 5.0, 0.0});
  // A gap of 2 mm between this run's buckets and its excess.
  driven("ours", "ideal", 90.0, 10.0, {1.0, 4.0, 0.0, -1.0, 5.0, 1.002});
  driven("ours", "field", 95.0, 15.0, {2.0, 4.0, 1.0, 0.0, 7.0, 1.0});
  // Not accounted: left out of the means.
  rows.push_back(row("system", "ours", "office", false, 30.0, 80.0, 1000.0));
  const std::string table = tableLosses(rows);
  EXPECT_NE(
      table.find(
          "\noffice:\n\n| planner | runs | travelled | excess | exploring | attempts | route switches | "
          "route choice | execution | push overhead |\n"),
      std::string::npos)
      << table;
  EXPECT_EQ(lineStartingWith(table, "| far |"),
            "| far | 2 | 110.0 | 30.0 | 5.0 | 0.0 | 5.0 | 15.0 | 5.0 | 0.0 |");
  EXPECT_EQ(lineStartingWith(table, "| ours |"),
            "| ours | 1 | 90.0 | 10.0 | 1.0 | 4.0 | 0.0 | -1.0 | 5.0 | 1.0 |");
  EXPECT_EQ(lineStartingWith(table, "| ours, field |"),
            "| ours, field | 1 | 95.0 | 15.0 | 2.0 | 4.0 | 1.0 | 0.0 | 7.0 | 1.0 |");
  EXPECT_EQ(lineStartingWith(table, "Largest"),
            "Largest difference between a run's buckets and its excess: 0.200 cm over 4 runs.");
  EXPECT_NE(tableLosses({}).find("No driven run was accounted."), std::string::npos);
}

}  // namespace
}  // namespace ifar::scenarios

namespace ifar::scenarios {
namespace {

TEST(InteractionGain, TheShareOfWhatPushingCouldSaveOverTheTasksBothArrivedOn)
{
  std::vector<ResultRow> rows;
  const auto driven = [&rows](const std::string& planner, const std::string& task, bool arrived,
                              double length) {
    ResultRow result = row("system", planner, "blocked_office", arrived, length, 44.0, 1000.0, task);
    result.achievable = 45.0;
    result.without_pushing = 90.0;  // pushing could save half
    rows.push_back(result);
  };
  // t0: FAR mode 100 m, ours 70 m; t1 as well but FAR mode did not arrive: left out.
  driven("far", "t0", true, 100.0);
  driven("ours", "t0", true, 70.0);
  driven("far", "t1", false, 300.0);
  driven("ours", "t1", true, 50.0);
  const std::string check = targetCheck(rows);
  // 30 % less travel of 50 % possible: 60 % captured.
  EXPECT_EQ(
      lineStartingWith(check, "| interaction gain captured >= 60% (blocked_office)"),
      "| interaction gain captured >= 60% (blocked_office) | 60% (30.0% less travel than FAR mode of 50.0% "
      "possible, 1 tasks) | met |");
  EXPECT_EQ(lineStartingWith(check, "| interaction gain captured >= 60% (office)"),
            "| interaction gain captured >= 60% (office) | - | not measured |");
}

}  // namespace
}  // namespace ifar::scenarios
