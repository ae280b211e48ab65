#pragma once
// The planner daemon's wiring: PlannerNode's inputs subscribed on the run loop, its tick, the worker's
// finished outputs and the path resend on the loop's timers. Apart from main() so a test can run it on an
// in-process bus with a manual clock (tests/replay/node_identity_test.cpp).

#include <memory>

#include <spdlog/spdlog.h>

#include "bus/run_loop.hpp"
#include "planner/core/planner.hpp"
#include "planner/daemon/planner_worker.hpp"
#include "planner/node/node_settings.hpp"
#include "planner/node/planner_node.hpp"

namespace ifar::planner {

class PlannerDaemon {
 public:
  /// Subscribes and sets the timers on `loop`, which must outlive this object.
  PlannerDaemon(bus::RunLoop& loop, const NodeSettings& settings, Planner planner,
                std::shared_ptr<spdlog::logger> logger, WorkerThreading threading);
  PlannerDaemon(const PlannerDaemon&) = delete;
  PlannerDaemon& operator=(const PlannerDaemon&) = delete;

  const PlannerNode& node() const { return node_; }

 private:
  void submit(std::optional<PlannerJob> job);
  void publishFinished();

  bus::RunLoop& loop_;
  NodeSettings settings_;
  PlannerNode node_;
  PlannerWorker worker_;
};

}  // namespace ifar::planner
