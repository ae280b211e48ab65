#pragma once
// The bus of the headless runner: what LCM and the CAN bus are between the daemons, in one process on
// simulated time. Nodes publish messages on named channels (and frames on the CAN bus); a publication is
// queued and delivered at the next deliver() to every subscriber of that channel with the time of
// delivery as its receive time, in the order published, as a daemon's run loop hands messages to its
// handlers. Messages published while delivering are delivered in the same call. Subscribing to a channel
// with another type than is published on it sees nothing, as a daemon whose decode fails. Every delivered
// message can be written to an LCM log, so a simulated run replays in lcm-spy and the replay tools.

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/lcm_log/log_writer.hpp"
#include "drivers/can/frame.hpp"
#include "ifar/affordance_t.hpp"
#include "ifar/blocked_passage_t.hpp"
#include "ifar/e_stop_t.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/force_t.hpp"
#include "ifar/goal_t.hpp"
#include "ifar/motor_status_t.hpp"
#include "ifar/odometry_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "ifar/world_state_t.hpp"

namespace ifar::runner {

/// Every message type the nodes exchange in a run.
using BusMessage = std::variant<ifar::velodyne_packet_t, ifar::pose_t, ifar::goal_t, ifar::path_t,
                                ifar::planner_status_t, ifar::force_t, ifar::motor_status_t, ifar::odometry_t,
                                ifar::velocity_cmd_t, ifar::exec_status_t, ifar::affordance_t,
                                ifar::blocked_passage_t, ifar::e_stop_t, ifar::world_state_t>;

/// Who is on the CAN bus: a frame reaches every participant but its sender.
using CanParticipant = int;

class SimulatedBus {
 public:
  /// `can_channel` names the CAN bus in the log (as the LCM bridge's channel, can_frame_t).
  explicit SimulatedBus(std::string can_channel);

  template <typename Message>
  void subscribe(const std::string& channel, std::function<void(const Message&, std::int64_t)> handler)
  {
    subscribers_[channel].push_back(
        [handler = std::move(handler)](const BusMessage& message, std::int64_t now_us) {
          if (const auto* typed = std::get_if<Message>(&message)) {
            handler(*typed, now_us);
          }
        });
  }
  void publish(std::string channel, BusMessage message);

  void subscribeFrames(CanParticipant participant,
                       std::function<void(const can::Frame&, std::int64_t)> handler);
  void publishFrame(CanParticipant sender, const can::Frame& frame);

  /// Delivers what is queued (and what handlers publish meanwhile) with receive time `now_us`.
  void deliver(std::int64_t now_us);
  /// Delivers only the queued CAN frames, to `participant` alone, and keeps them queued for the others.
  void deliverFramesTo(CanParticipant participant, std::int64_t now_us);

  /// Writes every message from now on to an LCM log at `path`; the reason when the file cannot be made.
  std::string recordTo(const std::string& path);
  /// Why recording stopped (a write failed); empty while it works or when not recording.
  const std::string& recordingError() const { return recording_error_; }

 private:
  struct Publication {
    std::string channel;
    std::optional<BusMessage> message;  // a message, or else
    std::optional<can::Frame> frame;    // a CAN frame from `sender`
    CanParticipant sender = 0;
    std::vector<CanParticipant> delivered;  // participants that already have the frame
  };
  void deliverMessage(const Publication& publication, std::int64_t now_us);
  void deliverFrame(Publication& publication, std::int64_t now_us);
  void record(const Publication& publication, std::int64_t now_us);

  std::string can_channel_;
  std::map<std::string, std::vector<std::function<void(const BusMessage&, std::int64_t)>>> subscribers_;
  std::map<CanParticipant, std::function<void(const can::Frame&, std::int64_t)>> frame_subscribers_;
  std::deque<Publication> queue_;
  std::unique_ptr<lcm_log::LogWriter> log_;
  std::string recording_error_;
};

}  // namespace ifar::runner
