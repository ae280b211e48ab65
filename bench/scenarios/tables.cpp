#include "bench/scenarios/tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench/scenarios/generalization_tables.hpp"
#include "bench/scenarios/scenario_kind.hpp"
#include "bench/scenarios/search_suite.hpp"
#include "bench/scenarios/table_text.hpp"
#include "common/percentile.hpp"

namespace ifar::scenarios {
namespace {

/// Milliseconds with about three significant digits.
std::string milliseconds(double value)
{
  if (!std::isfinite(value)) {
    return "-";
  }
  if (value >= 100.0) {
    return fixed(value, 0);
  }
  if (value >= 1.0) {
    return fixed(value, 2);
  }
  if (value >= 0.01) {
    return fixed(value, 3);
  }
  return fixed(value, 4);
}

/// The rows of `table` and `planner` whose kind is one of `kinds` ("office+willow" names both); system rows
/// only under the sensing profile `sensing`.
std::vector<const ResultRow*> select(const std::vector<ResultRow>& rows, const std::string& table,
                                     const std::string& planner, const std::string& kinds,
                                     const std::string& sensing = "ideal")
{
  std::vector<const ResultRow*> selected;
  for (const ResultRow& row : rows) {
    const bool kind_matches = ("+" + kinds + "+").find("+" + row.kind + "+") != std::string::npos;
    const bool sensing_matches = table != "system" || row.sensing == sensing;
    // Runner runs skipped for the time budget are left out (the notes count them), not scored as failures.
    if (row.table == table && row.planner == planner && kind_matches && sensing_matches &&
        row.status != "skipped") {
      selected.push_back(&row);
    }
  }
  return selected;
}

/// The sensing profiles of the system rows (sensingProfiles), "ideal" alone when there are none.
std::vector<std::string> tableProfiles(const std::vector<ResultRow>& rows)
{
  std::vector<std::string> profiles = sensingProfiles(rows);
  if (profiles.empty()) {
    profiles.emplace_back("ideal");
  }
  return profiles;
}

/// ", field" after a driven label for every profile but the ideal one.
std::string profileSuffix(const std::string& sensing)
{
  return sensing == "ideal" ? std::string() : ", " + sensing;
}

/// A success, and with `within` one that also arrived within that budget (driven rows).
bool succeeded(const ResultRow& row, const std::optional<SimTimeBudget>& within)
{
  return row.success && (!within || row.sim_time_s <= within->seconds(row.optimal));
}

int successes(const std::vector<const ResultRow*>& rows,
              const std::optional<SimTimeBudget>& within = std::nullopt)
{
  return static_cast<int>(std::count_if(rows.begin(), rows.end(),
                                        [&within](const ResultRow* row) { return succeeded(*row, within); }));
}

double medianMs(const std::vector<const ResultRow*>& rows)
{
  std::vector<double> times;
  for (const ResultRow* row : rows) {
    if (row->success && std::isfinite(row->ms)) {
      times.push_back(row->ms);
    }
  }
  return common::nearestRankPercentile(times, 50.0);
}

/// The median over the tasks both planners solved of the baseline's time over ours, and how many such
/// tasks there are. Medians over each planner's own successes compare different tasks when a baseline
/// solves few of them (grid A* solves one Willow task).
std::pair<double, int> pairedMedianRatio(const std::vector<const ResultRow*>& baseline,
                                         const std::vector<const ResultRow*>& ours)
{
  std::vector<double> ratios;
  for (const ResultRow* other : baseline) {
    for (const ResultRow* mine : ours) {
      if (other->world == mine->world && other->task == mine->task && other->success && mine->success &&
          std::isfinite(other->ms) && std::isfinite(mine->ms) && mine->ms > 0.0) {
        ratios.push_back(other->ms / mine->ms);
      }
    }
  }
  return {common::nearestRankPercentile(ratios, 50.0), static_cast<int>(ratios.size())};
}

/// Mean SPL against the ground truth, or (`achievable`) against Task::achievable; with `within`,
/// an arrival later than that budget counts as a failure.
double meanSpl(const std::vector<const ResultRow*>& rows, bool achievable = false,
               const std::optional<SimTimeBudget>& within = std::nullopt)
{
  if (rows.empty()) {
    return NAN;
  }
  double sum = 0.0;
  for (const ResultRow* row : rows) {
    sum += successWeightedByPathLength(succeeded(*row, within), achievable ? row->achievable : row->optimal,
                                       row->length);
  }
  return sum / static_cast<double>(rows.size());
}

double meanOptimal(const std::vector<ResultRow>& rows, const std::string& kind)
{
  double sum = 0.0;
  int count = 0;
  for (const ResultRow& row : rows) {
    if (row.table == "search" && row.kind == kind && row.planner == "ours") {
      sum += row.optimal;
      ++count;
    }
  }
  return count > 0 ? sum / count : NAN;
}

/// Mean SPL of a vehicle that drives each task's achievable path (static obstacles inflated, objects too
/// heavy to push as obstacles) against the ground truth; a task with no achievable path scores 0. NaN when
/// a row's achievable length is unknown.
double achievableSpl(const std::vector<const ResultRow*>& rows)
{
  if (rows.empty()) {
    return NAN;
  }
  double sum = 0.0;
  for (const ResultRow* row : rows) {
    if (std::isnan(row->achievable)) {
      return NAN;
    }
    sum += successWeightedByPathLength(std::isfinite(row->achievable), row->optimal, row->achievable);
  }
  return sum / static_cast<double>(rows.size());
}

bool anyRunnerRows(const std::vector<ResultRow>& rows)
{
  return std::any_of(rows.begin(), rows.end(), [](const ResultRow& row) {
    return row.table == "system" && row.status != "runner_unavailable";
  });
}

std::string header(const std::string& first)
{
  std::string line = "| " + first + " |";
  std::string rule = "|---|";
  for (const ScenarioKind kind : allKinds()) {
    line += " " + kindName(kind) + " |";
    rule += "---|";
  }
  return line + "\n" + rule + "\n";
}

/// The share of the travel pushing could save that the driven runs saved, per paper-like kind and the office.
std::string interactionGainTargets(const std::vector<ResultRow>& rows, bool runner)
{
  std::string text;
  for (const std::string kind : {"office", "blocked_office", "blocked_tunnel"}) {
    const std::string target = "| interaction gain captured >= 60% (" + kind + ") | ";
    if (!runner) {
      text += target + "runner unavailable | not measured |\n";
      continue;
    }
    // Over the tasks both modes drove to the goal: the travel pushing saved, against what it could save
    // there (1 - achievable / without pushing: the known-map ways with and without pushing).
    double far_travel = 0.0;
    double ours_travel = 0.0;
    double achievable = 0.0;
    double without_pushing = 0.0;
    int tasks = 0;
    for (const ResultRow* far : select(rows, "system", "far", kind)) {
      for (const ResultRow* ours : select(rows, "system", "ours", kind)) {
        if (far->world != ours->world || far->task != ours->task || !far->success || !ours->success ||
            !std::isfinite(far->length) || !std::isfinite(ours->length) || !std::isfinite(ours->achievable) ||
            !std::isfinite(ours->without_pushing)) {
          continue;
        }
        far_travel += far->length;
        ours_travel += ours->length;
        achievable += ours->achievable;
        without_pushing += ours->without_pushing;
        ++tasks;
      }
    }
    const double saved = 1.0 - ours_travel / far_travel;
    const double possible = 1.0 - achievable / without_pushing;
    const double captured = saved / possible;
    const bool measured = tasks > 0 && std::isfinite(captured) && possible > 0.0;
    text += target +
            (measured ? fixed(100.0 * captured, 0) + "% (" + fixed(100.0 * saved, 1) +
                            "% less travel than FAR mode of " + fixed(100.0 * possible, 1) + "% possible, " +
                            std::to_string(tasks) + " tasks)"
                      : std::string("-")) +
            " | " +
            (!measured         ? "not measured"
             : captured >= 0.6 ? "met"
                               : "missed") +
            " |\n";
  }
  return text;
}

/// The targets of driving under field sensing: SPL at least 0.95 of ideal sensing's at the same arrival rate,
/// planner frame p99 within 20 ms, and no push left at maximum force without a decision under any profile.
std::string sensingTargets(const std::vector<ResultRow>& rows)
{
  if (!anyRunnerRows(rows)) {
    return {};
  }
  std::string text;
  int undecided = 0;
  int driven = 0;
  for (const ResultRow& row : rows) {
    if (row.table == "system" && row.status != "skipped" && row.status != "runner_unavailable") {
      undecided += row.undecided_saturated_pushes;
      ++driven;
    }
  }
  text += "| no push held at maximum force past the tactile window + 2 s undecided (" +
          std::to_string(driven) + " driven runs) | " + std::to_string(undecided) + " | " +
          (undecided == 0 ? "met" : "missed") + " |\n";
  const std::vector<std::string> profiles = tableProfiles(rows);
  if (std::find(profiles.begin(), profiles.end(), "field") == profiles.end()) {
    return text;
  }
  for (const ScenarioKind kind : allKinds()) {
    const std::string name = kindName(kind);
    const auto field = select(rows, "system", "ours", name, "field");
    const auto ideal = select(rows, "system", "ours", name, "ideal");
    if (field.empty()) {
      continue;
    }
    const double field_spl = meanSpl(field);
    const double ideal_spl = meanSpl(ideal);
    // Each task is driven once under ideal (exact) and once per sensing seed under field: the arrival
    // rates are what compare.
    const bool same_rate = successes(field) * ideal.size() == successes(ideal) * field.size();
    const bool spl_met =
        std::isfinite(field_spl) && std::isfinite(ideal_spl) && field_spl >= 0.95 * ideal_spl && same_rate;
    std::vector<int> seeds;
    for (const ResultRow* row : field) {
      if (std::find(seeds.begin(), seeds.end(), row->sensing_seed) == seeds.end()) {
        seeds.push_back(row->sensing_seed);
      }
    }
    std::string where = name;
    if (seeds.size() > 1) {
      where += ", " + std::to_string(seeds.size()) + " sensing seeds";
    }
    text += "| ours driven SPL under field >= 0.95 x ideal, the same arrival rate (" + where + ") | " +
            fixed(field_spl, 3) + " (" + std::to_string(successes(field)) + "/" +
            std::to_string(field.size()) + ") vs " + fixed(ideal_spl, 3) + " (" +
            std::to_string(successes(ideal)) + "/" + std::to_string(ideal.size()) + ") | " +
            (spl_met ? "met" : "missed") + " |\n";
    double worst_p99 = NAN;
    for (const std::string planner : {"far", "ours"}) {
      for (const ResultRow* row : select(rows, "system", planner, name, "field")) {
        worst_p99 = std::fmax(worst_p99, row->frame_p99_ms);
      }
    }
    text += "| planner frame p99 <= 20 ms under field (" + name + ", worst run) | " + fixed(worst_p99, 1) +
            " ms | " +
            (!std::isfinite(worst_p99) ? "not measured"
             : worst_p99 <= 20.0       ? "met"
                                       : "missed") +
            " |\n";
  }
  return text;
}
}  // namespace

std::string tableOneSearchTime(const std::vector<ResultRow>& rows)
{
  std::string text =
      "Table I: search time per query, planner-thread CPU ms, median / p99 over the successful "
      "queries (successes / tasks).\n\n";
  text += header("planner");
  text += "| optimal length, mean (m) |";
  for (const ScenarioKind kind : allKinds()) {
    text += " " + fixed(meanOptimal(rows, kindName(kind)), 1) + " |";
  }
  text += "\n";
  for (const std::string& planner : searchPlanners()) {
    text += "| " + planner + " |";
    for (const ScenarioKind kind : allKinds()) {
      const auto selected = select(rows, "search", planner, kindName(kind));
      std::vector<double> times;
      for (const ResultRow* row : selected) {
        if (row->success && std::isfinite(row->ms)) {
          times.push_back(row->ms);
        }
      }
      text += " " + milliseconds(common::nearestRankPercentile(times, 50.0)) + " / " +
              milliseconds(common::nearestRankPercentile(times, 99.0)) + " (" +
              std::to_string(successes(selected)) + "/" + std::to_string(selected.size()) + ") |";
    }
    text += "\n";
  }
  return text;
}

std::string tableTwoSpl(const std::vector<ResultRow>& rows, const std::optional<SimTimeBudget>& stricter)
{
  std::string text =
      "Table II: SPL = mean over tasks of success x optimal / max(length, optimal). Planned: the "
      "path each planner returns (movable objects are obstacles unless the planner pushes). "
      "Driven: the distance the vehicle travelled in the headless runner.\n\n";
  text += header("planner");
  for (const std::string& planner : searchPlanners()) {
    text += "| " + planner + " (planned) |";
    for (const ScenarioKind kind : allKinds()) {
      const auto selected = select(rows, "search", planner, kindName(kind));
      text += " " + fixed(meanSpl(selected), 3) + " (" + std::to_string(successes(selected)) + "/" +
              std::to_string(selected.size()) + ") |";
    }
    text += "\n";
  }
  const bool runner = anyRunnerRows(rows);
  struct DrivenVariant {
    std::string label;
    bool achievable;
    std::optional<SimTimeBudget> within;
  };
  std::vector<DrivenVariant> variants{{" (driven)", false, std::nullopt},
                                      {" (driven, vs achievable)", true, std::nullopt}};
  if (stricter && runner) {
    variants.push_back({" (driven, arrived within " + stricter->describe() + ")", false, stricter});
  }
  for (const std::string& sensing : tableProfiles(rows)) {
    for (const DrivenVariant& variant : variants) {
      for (const std::string planner : {"far", "ours"}) {
        std::string label = "| " + planner + variant.label;
        label.insert(label.size() - 1, profileSuffix(sensing));
        text += label;
        text += " |";
        for (const ScenarioKind kind : allKinds()) {
          const auto selected = select(rows, "system", planner, kindName(kind), sensing);
          if (!runner) {
            text += " runner unavailable |";
          } else if (selected.empty()) {
            text += " not run |";
          } else {
            text += " " + fixed(meanSpl(selected, variant.achievable, variant.within), 3) + " (" +
                    std::to_string(successes(selected, variant.within)) + "/" +
                    std::to_string(selected.size()) + ") |";
          }
        }
        text += "\n";
      }
    }
  }
  text +=
      "\n\"field\": the simulator's field sensing profile (pose drift, jitter and jumps, lidar noise and "
      "dropouts, wheel slip, force sensor noise; docs/simulator.md); the others are under ideal sensing.\n"
      "\"vs achievable\": SPL against the shortest path a vehicle that knew the map could drive (static "
      "obstacles inflated by its half width, objects too heavy to push as obstacles), not the issue's ground "
      "truth; the gap between the two rows is what the world allows no planner, the rest is exploration and "
      "execution.\n";
  if (stricter && runner) {
    text += "\"arrived within " + stricter->describe() +
            "\": the same runs with an arrival later than that (simulated time, on the optimum) counted as a "
            "failure.\n";
  }
  return text;
}

std::string tableThreeSystem(const std::vector<ResultRow>& rows)
{
  const std::vector<std::string> kinds{"office", "willow", "tunnel", "blocked_office", "blocked_tunnel"};
  std::string text =
      "Table III: system level, headless runner: travel distance and simulated time summed over "
      "the tasks, success.\n\n| planner |";
  std::string rule = "|---|";
  for (const std::string& kind : kinds) {
    text.append(" ").append(kind).append(" distance (m) | ").append(kind).append(" time (s) | ");
    text.append(kind).append(" success |");
    rule += "---|---|---|";
  }
  text += "\n" + rule + "\n";
  const bool runner = anyRunnerRows(rows);
  for (const std::string& sensing : tableProfiles(rows)) {
    for (const std::string planner : {"far", "ours"}) {
      text += "| " + planner + (sensing == "ideal" ? std::string() : " (" + sensing + ")") + " |";
      for (const std::string& kind : kinds) {
        const auto selected = select(rows, "system", planner, kind, sensing);
        if (!runner) {
          text += " runner unavailable | - | - |";
          continue;
        }
        double distance = 0.0;
        double time = 0.0;
        for (const ResultRow* row : selected) {
          distance += std::isfinite(row->length) ? row->length : 0.0;
          time += row->sim_time_s;
        }
        text += " " + fixed(distance, 1) + " | " + fixed(time, 1) + " | " +
                std::to_string(successes(selected)) + "/" + std::to_string(selected.size()) + " |";
      }
      text += "\n";
    }
  }
  return text;
}

std::string tableLosses(const std::vector<ResultRow>& rows)
{
  std::string text =
      "Loss accounting: the distance driven beyond the achievable way (travelled - (achievable - left at the "
      "end)) and where it went, metres per run, mean over the runs accounted (docs/benchmarks.md, \"Loss "
      "accounting\").\n";
  double largest_gap = 0.0;
  int accounted = 0;
  for (const ScenarioKind kind : allKinds()) {
    std::string body;
    for (const std::string& sensing : tableProfiles(rows)) {
      for (const std::string planner : {"far", "ours"}) {
        std::vector<const ResultRow*> selected;
        for (const ResultRow* row : select(rows, "system", planner, kindName(kind), sensing)) {
          if (std::isfinite(row->excess_m)) {
            selected.push_back(row);
          }
        }
        if (selected.empty()) {
          continue;
        }
        const double runs = static_cast<double>(selected.size());
        double travelled = 0.0;
        double excess = 0.0;
        runner::LossBuckets sums;
        for (const ResultRow* row : selected) {
          travelled += row->length;
          excess += row->excess_m;
          for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
            runner::lossBucket(sums, bucket) += runner::lossBucket(row->losses, bucket);
          }
          largest_gap = std::fmax(largest_gap, std::abs(row->losses.total() - row->excess_m));
          ++accounted;
        }
        body += "| " + planner + profileSuffix(sensing) + " | " + std::to_string(selected.size()) + " | " +
                fixed(travelled / runs, 1) + " | " + fixed(excess / runs, 1) + " |";
        for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
          body += " " + fixed(runner::lossBucket(sums, bucket) / runs, 1) + " |";
        }
        body += "\n";
      }
    }
    if (body.empty()) {
      continue;
    }
    text += "\n" + kindName(kind) + ":\n\n| planner | runs | travelled | excess |";
    for (int bucket = 0; bucket < runner::kLossBucketCount; ++bucket) {
      std::string name = runner::lossBucketName(bucket);
      std::replace(name.begin(), name.end(), '_', ' ');
      text += " " + name + " |";
    }
    text += "\n|---|---|---|---|---|---|---|---|---|---|\n" + body;
  }
  if (accounted == 0) {
    return text + "\nNo driven run was accounted.\n";
  }
  return text +
         "\nLargest difference between a run's buckets and its excess: " + fixed(largest_gap * 100.0, 3) +
         " cm over " + std::to_string(accounted) + " runs.\n";
}

std::string tablePlannerFrames(const std::vector<ResultRow>& rows, int parallel_runs)
{
  const std::string sharing =
      parallel_runs == 1 ? std::string("one run at a time") : std::to_string(parallel_runs) + " runs at once";
  std::string text = "Planner frames in the driven runs, wall ms (" + sharing +
                     " on the machine's cores): median of the runs' medians / worst run's p99 / longest "
                     "frame; in brackets the longest interaction stage (no frame budget in the runner).\n\n";
  text += header("planner");
  for (const std::string& sensing : tableProfiles(rows)) {
    for (const std::string planner : {"far", "ours"}) {
      text += "| " + planner + (sensing == "ideal" ? std::string() : " (" + sensing + ")") + " |";
      for (const ScenarioKind kind : allKinds()) {
        std::vector<double> medians;
        double worst_p99 = NAN;
        double longest = NAN;
        double longest_interaction = NAN;
        for (const ResultRow* row : select(rows, "system", planner, kindName(kind), sensing)) {
          if (!std::isfinite(row->frame_median_ms)) {
            continue;  // not run, or no planner frame
          }
          medians.push_back(row->frame_median_ms);
          worst_p99 = std::fmax(worst_p99, row->frame_p99_ms);
          longest = std::fmax(longest, row->frame_max_ms);
          longest_interaction = std::fmax(longest_interaction, row->interaction_max_ms);
        }
        text += medians.empty() ? std::string(" - |")
                                : " " + fixed(common::nearestRankPercentile(medians, 50.0), 1) + " / " +
                                      fixed(worst_p99, 1) + " / " + fixed(longest, 1) + " (" +
                                      fixed(longest_interaction, 1) + ") |";
      }
      text += "\n";
    }
  }
  return text;
}

std::string targetCheck(const std::vector<ResultRow>& rows)
{
  std::string text = "| target | measured | verdict |\n|---|---|---|\n";
  const auto ratio_line = [&](const std::string& baseline, const std::string& kind) {
    const std::vector<const ResultRow*> ours_rows = select(rows, "search", "ours", kind);
    const std::vector<const ResultRow*> baseline_rows = select(rows, "search", baseline, kind);
    const double ours = medianMs(ours_rows);
    const double other = medianMs(baseline_rows);
    const double ratio = other / ours;
    const auto [paired, pairs] = pairedMedianRatio(baseline_rows, ours_rows);
    text += "| ours >= 10x faster than " + baseline + " (" + kind + ", median) | " +
            (std::isfinite(ratio) ? fixed(ratio, 1) + "x" : std::string("-")) + " (" + milliseconds(other) +
            " vs " + milliseconds(ours) + " ms; per task, on the " + std::to_string(pairs) +
            " both solve: median " + (std::isfinite(paired) ? fixed(paired, 1) + "x" : std::string("-")) +
            ") | " +
            (!std::isfinite(ratio) ? "not measured"
             : ratio >= 10.0       ? "met"
                                   : "missed") +
            " |\n";
  };
  // The Office is the Willow Garage plan plus the generated offices: "office+willow" pools them.
  for (const std::string kind : {"office", "willow", "office+willow", "tunnel"}) {
    ratio_line("grid_astar", kind);
    ratio_line("bit_star", kind);
  }
  const bool runner = anyRunnerRows(rows);
  const auto spl_line = [&](const std::string& table, const std::string& kind, double target) {
    const auto selected = select(rows, table, "ours", kind);
    const double spl = meanSpl(selected);
    // The most any vehicle scores is following each achievable path: when that is below the target, the
    // world, not the planner, decides the verdict. (Planned rows may score more: they plan every object
    // with the prior mass, heavy crates included.)
    const double ceiling = achievableSpl(selected);
    const std::string beside =
        std::isfinite(ceiling) ? "; the achievable paths: " + fixed(ceiling, 3) : std::string();
    std::string verdict = !std::isfinite(spl) ? "not measured"
                          : spl >= target     ? "met"
                                              : "missed by " + fixed(target - spl, 3);
    if (std::isfinite(spl) && spl < target && ceiling < target) {
      verdict += ", beyond any vehicle in these worlds";
    }
    text += "| SPL " + kind + " >= " + fixed(target, 2) + " (" + (table == "system" ? "driven" : "planned") +
            ") | " + fixed(spl, 3) + ", success " + std::to_string(successes(selected)) + "/" +
            std::to_string(selected.size()) + beside + " | " + verdict + " |\n";
  };
  // Planned is the paper's Table II (paths on the known map, as its A*, RRT* and BIT* rows); driven is
  // what the vehicle travelled exploring the unknown world in the runner.
  const std::vector<std::pair<std::string, double>> spl_targets{
      {"room_objects", 0.80}, {"office", 0.90}, {"willow", 0.90}, {"office+willow", 0.90}, {"tunnel", 0.97}};
  for (const std::string table : {"search", "system"}) {
    if (table == "system" && !runner) {
      continue;
    }
    for (const auto& [kind, target] : spl_targets) {
      spl_line(table, kind, target);
    }
  }
  for (const std::string kind : {"office", "office+willow", "blocked_office"}) {
    if (!runner) {
      text +=
          "| ours travels >= 40% less than FAR mode (" + kind + ") | runner unavailable | not measured |\n";
      continue;
    }
    double far_distance = 0.0;
    double ours_distance = 0.0;
    double optimal_distance = 0.0;
    for (const ResultRow* row : select(rows, "system", "far", kind)) {
      far_distance += std::isfinite(row->length) ? row->length : 0.0;
    }
    for (const ResultRow* row : select(rows, "system", "ours", kind)) {
      ours_distance += std::isfinite(row->length) ? row->length : 0.0;
      optimal_distance += row->optimal;
    }
    const double shorter = 1.0 - ours_distance / far_distance;
    // No drive is shorter than the ground-truth optimum, so this is the most any planner could save.
    const double bound = 1.0 - optimal_distance / far_distance;
    text += "| ours travels >= 40% less than FAR mode (" + kind + ") | " +
            (std::isfinite(shorter) ? fixed(100.0 * shorter, 1) + "%" : std::string("-")) +
            " (the optimal lengths: " +
            (std::isfinite(bound) ? fixed(100.0 * bound, 1) + "%" : std::string("-")) + " less) | " +
            (!std::isfinite(shorter) ? "not measured"
             : shorter >= 0.4        ? "met"
                                     : "missed") +
            " |\n";
  }
  text += interactionGainTargets(rows, runner);
  text += sensingTargets(rows);
  text += generalizationTargets(rows);
  return text;
}

}  // namespace ifar::scenarios
