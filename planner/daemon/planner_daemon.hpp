#pragma once
// The planner daemon's wiring: PlannerNode's inputs subscribed on the run loop, its tick, the worker's
// finished outputs and the path resend on the loop's timers, and what it handed the node journaled. Apart
// from main() so a test can run it on an in-process bus with a manual clock
// (tests/replay/node_identity_test.cpp).

#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include <spdlog/spdlog.h>

#include "bus/node_journal_publisher.hpp"
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
  /// The configuration the node runs with (YAML), for the journal's first batch: a replay-test of the
  /// log then needs no config of its own for the node.
  void setJournalSettings(std::string yaml) { journal_.recorder().setSettings(std::move(yaml)); }

 private:
  void submit(std::optional<PlannerJob> job);
  void publishFinished();

  bus::RunLoop& loop_;
  NodeSettings settings_;
  std::int64_t start_utime_;  // the node's clock origin, as its journal states it
  PlannerNode node_;
  PlannerWorker worker_;
  bus::NodeJournalPublisher journal_;  // last: goes first, publishing its rest while the rest still exists
};

}  // namespace ifar::planner
