#include "bench/scenarios/generalization_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bench/scenarios/driven_outcome.hpp"
#include "bench/scenarios/table_text.hpp"

namespace ifar::scenarios {
namespace {

const char* const kKinds[] = {"namosim", "willow_pairs"};

bool driven(const ResultRow& row)
{
  return row.table == "system" && row.status != "skipped" && row.status != "runner_unavailable";
}

std::vector<const ResultRow*> drivenRows(const std::vector<ResultRow>& rows, const std::string& kind,
                                         const std::string& planner, const std::string& sensing)
{
  std::vector<const ResultRow*> selected;
  for (const ResultRow& row : rows) {
    if (driven(row) && row.kind == kind && row.planner == planner && row.sensing == sensing) {
      selected.push_back(&row);
    }
  }
  return selected;
}

bool reachable(const ResultRow& row)
{
  return std::isfinite(row.achievable);
}

/// What the scores of one kind, mode and profile add up to.
struct Summary {
  int runs = 0;
  int arrived = 0;
  int reachable = 0;
  int arrived_reachable = 0;
  int never_pushing = 0;        // reachable without pushing
  double spl_achievable = NAN;  // mean over the reachable runs
  double spl_optimal = NAN;     // mean over all runs
  int no_path_pushing_required = 0;
  int no_path = 0;
  int no_path_never_pushing = 0;  // "no path" although a way that never pushes exists
  int time_limit = 0;
  int failed = 0;
};

Summary summarize(const std::vector<const ResultRow*>& rows)
{
  Summary summary;
  double achievable_sum = 0.0;
  double optimal_sum = 0.0;
  for (const ResultRow* row : rows) {
    ++summary.runs;
    summary.arrived += row->success ? 1 : 0;
    summary.never_pushing += std::isfinite(row->without_pushing) ? 1 : 0;
    optimal_sum += successWeightedByPathLength(row->success, row->optimal, row->length);
    if (reachable(*row)) {
      ++summary.reachable;
      summary.arrived_reachable += row->success ? 1 : 0;
      achievable_sum += successWeightedByPathLength(row->success, row->achievable, row->length);
    }
    if (row->status == "no_path_pushing_required") {
      ++summary.no_path_pushing_required;
    } else if (row->status == "no_path") {
      ++summary.no_path;
      summary.no_path_never_pushing += std::isfinite(row->without_pushing) ? 1 : 0;
    } else if (row->status == "time_limit") {
      ++summary.time_limit;
    } else if (!row->success) {
      ++summary.failed;
    }
  }
  if (summary.runs > 0) {
    summary.spl_optimal = optimal_sum / summary.runs;
  }
  if (summary.reachable > 0) {
    summary.spl_achievable = achievable_sum / summary.reachable;
  }
  return summary;
}

std::string modeName(const std::string& planner)
{
  return planner == "far" ? "FAR mode" : "ours";
}

/// A reason short enough for a table cell, its pipes escaped.
std::string cell(const std::string& text)
{
  constexpr std::size_t kLongest = 160;
  std::string shortened = text.size() > kLongest ? text.substr(0, kLongest) + "..." : text;
  std::string escaped;
  for (const char character : shortened) {
    if (character == '|') {
      escaped += "\\|";
    } else if (character != '\n') {
      escaped += character;
    }
  }
  return escaped;
}

const ResultRow* partner(const std::vector<const ResultRow*>& rows, const ResultRow& row)
{
  for (const ResultRow* other : rows) {
    if (other->world == row.world && other->task == row.task) {
      return other;
    }
  }
  return nullptr;
}

std::string outcome(const ResultRow* row)
{
  if (row == nullptr) {
    return "-";
  }
  return row->status + (std::isfinite(row->length) ? " " + fixed(row->length, 1) + " m" : std::string());
}

std::string verdict(bool measured, bool met)
{
  return !measured ? "not measured" : met ? "met" : "missed";
}

}  // namespace

std::string tableGeneralization(const std::vector<ResultRow>& rows)
{
  const std::vector<std::string> sensing = sensingProfiles(rows);
  std::string text;
  for (const std::string kind : kKinds) {
    for (const std::string& profile : sensing) {
      for (const std::string planner : {"far", "ours"}) {
        const Summary summary = summarize(drivenRows(rows, kind, planner, profile));
        if (summary.runs == 0) {
          continue;
        }
        const std::vector<std::string> cells{
            kind,
            modeName(planner),
            profile,
            std::to_string(summary.runs),
            std::to_string(summary.arrived),
            std::to_string(summary.arrived_reachable) + "/" + std::to_string(summary.reachable),
            std::to_string(summary.never_pushing),
            fixed(summary.spl_achievable, 3),
            fixed(summary.spl_optimal, 3),
            std::to_string(summary.no_path_pushing_required),
            std::to_string(summary.no_path) + " (" + std::to_string(summary.no_path_never_pushing) + ")",
            std::to_string(summary.time_limit),
            std::to_string(summary.failed)};
        text += "|";
        for (const std::string& value : cells) {
          text.append(" ").append(value).append(" |");
        }
        text += "\n";
      }
    }
  }
  if (text.empty()) {
    return {};
  }
  text =
      "Generalization (worlds nobody here made; driven). Reachable: a vehicle that knew the map and pushed "
      "the light objects has a way (achievable); never pushing: it has one without pushing. SPL vs "
      "achievable is over the reachable runs (the known-map optimum with pushes), vs optimal over all "
      "runs. No path (never pushing): runs ended with the planner reporting no path, and of those how "
      "many had a way that never pushes.\n\n"
      "| kind | mode | sensing | runs | arrived | arrived / reachable | never pushing | SPL vs achievable | "
      "SPL vs optimal | no path, pushing required | no path (never pushing) | time limit | failed |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n" +
      text;
  if (sensing.empty()) {
    return text;
  }
  const std::string& first = sensing.front();
  const std::vector<const ResultRow*> far_goals = drivenRows(rows, "namosim", "far", first);
  const std::vector<const ResultRow*> our_goals = drivenRows(rows, "namosim", "ours", first);
  if (!our_goals.empty() || !far_goals.empty()) {
    text +=
        "\nNamosim, goal by goal (" + first +
        " sensing; each goal driven from the one before, the world as the file has it):\n\n"
        "| world | goal | achievable m | never pushing m | FAR mode | ours | ours SPL vs achievable | why "
        "not arrived |\n|---|---|---|---|---|---|---|---|\n";
    const std::vector<const ResultRow*>& listed = our_goals.empty() ? far_goals : our_goals;
    for (const ResultRow* row : listed) {
      const ResultRow* far = partner(far_goals, *row);
      const ResultRow* ours = partner(our_goals, *row);
      std::string why;
      if (ours != nullptr && !ours->success) {
        why = "ours: " + ours->reason;
      }
      if (far != nullptr && !correctOutcome(far->status)) {
        why += (why.empty() ? "" : "; ") + std::string("FAR: ") + far->reason;
      }
      const double spl = ours == nullptr ? NAN
                         : reachable(*ours)
                             ? successWeightedByPathLength(ours->success, ours->achievable, ours->length)
                             : NAN;
      text += "| " + row->world + " | " + row->task + " | " + fixed(row->achievable, 1) + " | " +
              fixed(row->without_pushing, 1) + " | " + outcome(far) + " | " + outcome(ours) + " | " +
              fixed(spl, 3) + " | " + cell(why) + " |\n";
    }
  }
  std::string misses;
  for (const std::string planner : {"far", "ours"}) {
    for (const ResultRow* row : drivenRows(rows, "willow_pairs", planner, first)) {
      if (!row->success) {
        misses += "| " + row->task + " | " + modeName(planner) + " | " + fixed(row->optimal, 1) + " | " +
                  outcome(row) + " | " + cell(row->reason) + " |\n";
      }
    }
  }
  if (!misses.empty()) {
    text += "\nWillow pairs that did not arrive (" + first +
            " sensing):\n\n| pair | mode | optimal m | outcome | reason |\n|---|---|---|---|---|\n" + misses;
  }
  return text;
}

std::string generalizationTargets(const std::vector<ResultRow>& rows)
{
  std::string text;
  const std::vector<const ResultRow*> ours = drivenRows(rows, "namosim", "ours", "ideal");
  if (!ours.empty()) {
    const Summary summary = summarize(ours);
    const bool met = summary.arrived_reachable == summary.reachable && summary.spl_achievable >= 0.8;
    text +=
        "| namosim: ours arrives on every goal a pushing vehicle can reach, SPL vs achievable >= 0.80 | " +
        std::to_string(summary.arrived_reachable) + "/" + std::to_string(summary.reachable) + ", SPL " +
        fixed(summary.spl_achievable, 3) + " | " + verdict(summary.reachable > 0, met) + " |\n";
  }
  const std::vector<const ResultRow*> far = drivenRows(rows, "namosim", "far", "ideal");
  if (!far.empty()) {
    const Summary summary = summarize(far);
    int pushing_required = 0;
    for (const ResultRow* row : far) {
      pushing_required += std::isfinite(row->without_pushing) ? 0 : 1;
    }
    text += "| namosim: FAR mode reports no path only where pushing is required | " +
            std::to_string(summary.no_path_never_pushing) + " no path with a way that never pushes; " +
            std::to_string(summary.no_path_pushing_required) + " of " + std::to_string(pushing_required) +
            " goals that need a push reported as no path | " +
            verdict(true, summary.no_path_never_pushing == 0) + " |\n";
  }
  const std::vector<const ResultRow*> pairs = drivenRows(rows, "willow_pairs", "ours", "ideal");
  if (!pairs.empty()) {
    const Summary summary = summarize(pairs);
    const double share = static_cast<double>(summary.arrived) / summary.runs;
    // Against the achievable length: the zero-inflation optimum threads gaps in the floor plan narrower than
    // the vehicle, up to three times shorter than any way it fits through.
    text += "| willow_pairs: ours arrives >= 95 %, SPL vs achievable >= 0.90 | " + fixed(100.0 * share, 1) +
            " % (" + std::to_string(summary.arrived) + "/" + std::to_string(summary.runs) + "), SPL " +
            fixed(summary.spl_achievable, 3) + " | " +
            verdict(true, share >= 0.95 && summary.spl_achievable >= 0.9) + " |\n";
  }
  int time_limit = 0;
  int runs = 0;
  for (const std::string kind : kKinds) {
    for (const std::string planner : {"far", "ours"}) {
      for (const std::string& profile : sensingProfiles(rows)) {
        const Summary summary = summarize(drivenRows(rows, kind, planner, profile));
        time_limit += summary.time_limit;
        runs += summary.runs;
      }
    }
  }
  if (runs > 0) {
    text += "| no generalization run ends by the time limit (" + std::to_string(runs) + " runs) | " +
            std::to_string(time_limit) + " | " + verdict(true, time_limit == 0) + " |\n";
  }
  return text;
}

}  // namespace ifar::scenarios
