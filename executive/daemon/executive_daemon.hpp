#pragma once
// The executive daemon's wiring: ExecutiveNode's inputs subscribed on the run loop and its control cycle
// on the loop's 50 Hz timer, outputs published, and what it handed the node journaled. Apart from main() so a
// test can run it on an in-process bus with a manual clock (tests/replay/node_identity_test.cpp).

#include <memory>
#include <string>
#include <utility>

#include <spdlog/spdlog.h>

#include "bus/node_journal_publisher.hpp"
#include "bus/run_loop.hpp"
#include "executive/node/executive_node.hpp"

namespace ifar::executive {

class ExecutiveDaemon {
 public:
  /// Subscribes on `loop` (which must outlive this object) and runs a control cycle every kControlPeriodS.
  ExecutiveDaemon(bus::RunLoop& loop, const ExecutiveSettings& settings, const ObstacleSettings& obstacles,
                  const common::VehicleSettings& vehicle, std::shared_ptr<spdlog::logger> logger);
  ExecutiveDaemon(const ExecutiveDaemon&) = delete;
  ExecutiveDaemon& operator=(const ExecutiveDaemon&) = delete;

  /// Publishes the node's stop outputs (a zero command, the last status again).
  void publishStop();
  const ExecutiveNode& node() const { return node_; }
  /// The configuration the node runs with (YAML), for the journal's first batch (PlannerDaemon's).
  void setJournalSettings(std::string yaml) { journal_.recorder().setSettings(std::move(yaml)); }

 private:
  void publish(const ExecutiveOutputs& outputs);

  bus::RunLoop& loop_;
  ExecutiveNode node_;
  bus::NodeJournalPublisher journal_;  // what the loop handed the node, for ifar replay-test
};

}  // namespace ifar::executive
