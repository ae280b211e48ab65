#pragma once
// Runs the Planner on its own thread so a slow frame never blocks the LCM loop. The loop hands over at
// most one job at a time (the latest frame and goal change); while the worker is busy a new job is
// refused and counted as a dropped frame. Finished results are picked up by the loop and published.

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "planner/core/planner.hpp"

namespace ifar::planner {

struct PlannerJob {
  std::optional<FrameInput> frame;  // nullopt: replan only (a goal or an affordance changed)
  std::optional<Goal> new_goal;
  bool clear_goal = false;
  std::vector<AffordanceUpdate> affordances;     // applied first, in order
  std::vector<BlockedPassage> blocked_passages;  // then these, in order
};

/// `Output` is what the worker hands back, built on the worker thread where the graph lives.
template <typename Output>
class PlannerWorker {
 public:
  /// `convert` turns the planner and a finished frame into the output (runs on the worker thread).
  using Convert = std::function<Output(const Planner&, const FrameResult&, const std::string& goal_problem)>;

  PlannerWorker(Planner planner, Convert convert)
      : planner_(std::move(planner)), convert_(std::move(convert)), thread_([this] { loop(); })
  {
  }
  ~PlannerWorker()
  {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  PlannerWorker(const PlannerWorker&) = delete;
  PlannerWorker& operator=(const PlannerWorker&) = delete;

  /// False (the job is not taken) while the previous job is still running or waiting.
  bool trySubmit(PlannerJob job)
  {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (job_ || busy_) {
        return false;
      }
      job_ = std::move(job);
    }
    wake_.notify_one();
    return true;
  }
  /// The finished outputs since the last call.
  std::vector<Output> takeFinished()
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Output> finished;
    finished.swap(finished_);
    return finished;
  }

 private:
  void loop()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      wake_.wait(lock, [this] { return stopping_ || job_.has_value(); });
      if (stopping_) {
        return;
      }
      PlannerJob job = std::move(*job_);
      job_.reset();
      busy_ = true;
      lock.unlock();
      Output output = run(job);
      lock.lock();
      busy_ = false;
      finished_.push_back(std::move(output));
    }
  }
  Output run(const PlannerJob& job)
  {
    std::string goal_problem;
    if (job.clear_goal) {
      planner_.clearGoal();
    }
    if (job.new_goal && !planner_.setGoal(*job.new_goal)) {
      goal_problem = "goal " + std::to_string(job.new_goal->id) + " refused: coordinates are not finite";
    }
    FrameResult result;
    try {
      std::optional<FrameResult> update_result;
      for (const AffordanceUpdate& update : job.affordances) {
        update_result = planner_.applyAffordance(update);
      }
      for (const BlockedPassage& passage : job.blocked_passages) {
        update_result = planner_.applyBlockedPassage(passage);
      }
      if (job.frame) {
        result = planner_.processFrame(*job.frame);
      } else if (update_result && !job.new_goal && !job.clear_goal) {
        result = std::move(*update_result);  // already searched again
      } else {
        result = planner_.replan();
      }
    } catch (const std::exception& error) {
      // A library failure costs this update, never the process: reported like rejected input.
      result.status.state = PlannerState::BadInput;
      result.status.message = std::string("planner update failed: ") + error.what();
    }
    return convert_(planner_, result, goal_problem);
  }

  Planner planner_;  // only touched by the worker thread once it runs
  Convert convert_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<PlannerJob> job_;
  std::vector<Output> finished_;
  bool busy_ = false;
  bool stopping_ = false;
  std::thread thread_;  // last: starts after every member above exists
};

}  // namespace ifar::planner
