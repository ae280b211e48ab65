#pragma once
// Runs the Planner on its own thread so a slow frame never blocks the LCM loop. The loop hands over at
// most one job at a time and takes its outputs before the next; while the worker is busy the node keeps the
// next one (PlannerNode counts a revolution it had to hold back as dropped). Finished outputs are picked up
// by the loop and published. In line (a test replaying a log on a manual clock) each job runs at once on the
// caller's thread.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "planner/core/planner.hpp"
#include "planner/node/planner_job.hpp"

namespace ifar::planner {

enum class WorkerThreading { OwnThread, InLine };

class PlannerWorker {
 public:
  /// `clock` stamps the outputs (microseconds; called on the worker thread).
  PlannerWorker(Planner planner, std::function<std::int64_t()> clock, WorkerThreading threading);
  ~PlannerWorker();
  PlannerWorker(const PlannerWorker&) = delete;
  PlannerWorker& operator=(const PlannerWorker&) = delete;

  /// True from submit() until takeFinished() has returned the job's outputs: whether the loop may hand
  /// over the next job then depends on the loop's own steps alone, so its journal replays it.
  bool busy() const;
  /// Hands `job` over; the caller checks busy() first (a job given to a busy worker is a bug: it throws).
  void submit(PlannerJob job);
  /// The finished outputs since the last call.
  std::vector<PlannerOutputs> takeFinished();

 private:
  void loop();
  PlannerOutputs run(const PlannerJob& job);

  Planner planner_;  // only touched by the worker thread once it runs
  std::function<std::int64_t()> clock_;
  WorkerThreading threading_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<PlannerJob> job_;
  std::vector<PlannerOutputs> finished_;
  bool busy_ = false;
  bool stopping_ = false;
  std::thread thread_;  // last: starts after every member above exists
};

}  // namespace ifar::planner
