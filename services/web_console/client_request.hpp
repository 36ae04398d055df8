#pragma once
// What a client may send over the WebSocket, and the judge of every message before anything
// acts on it. Text JSON objects:
//   {"type": "goal", "token": "...", "x": 1.5, "y": 2.0, "theta": 0.0}   drive to (x, y) [m], theta [rad]
//   {"type": "stop", "token": "..."}                                      cancel the goal, stop
//   {"type": "initial_pose", "token": "...", "x": .., "y": .., "theta": ..}  "the robot is here":
//                                                                         INITIAL_POSE, a prior the matcher
//                                                                         verifies
// Refused (and counted by reason, never acted on): larger than max_message_bytes ("too_large"),
// not JSON ("not_json"), not an object or without a string "type" ("not_an_object"), a type not
// listed ("unknown_type"), any command while control is off ("control_disabled"), a missing or
// wrong token ("bad_token"), a coordinate missing, not a number, non-finite or out of bounds
// ("bad_number").

#include "web_console/console_config.hpp"

#include <optional>
#include <string>

namespace refloc {

struct ConsoleCommand {
  enum class Kind { kGoal, kStop, kInitialPose };
  Kind kind = Kind::kStop;
  double x = 0.0;      ///< goal or initial pose [m], map frame
  double y = 0.0;      ///< [m]
  double theta = 0.0;  ///< [rad]
};

struct RequestVerdict {
  std::optional<ConsoleCommand> command;  ///< set when accepted
  const char* refusal = nullptr;          ///< the reason when refused (a counter suffix)
};

/// The answer to the client that sent a message: {"type":"command_result","ok":true,"command":"goal"}
/// or {"type":"command_result","ok":false,"reason":"bad_token"}; refusal overrides an accepted
/// verdict (the inbox was full).
std::string command_result_frame(const RequestVerdict& verdict, const char* refusal = nullptr);

/// Goal coordinates beyond this are refused [m]: no site is 10 km across.
inline constexpr double kMaxGoalCoordinate_m = 1e4;

class RequestValidator {
 public:
  RequestValidator(const ConsoleControlConfig& control, size_t max_message_bytes)
      : control_(control), max_message_bytes_(max_message_bytes) {}

  RequestVerdict judge(const std::string& message) const;

 private:
  bool token_matches(const std::string& token) const;

  ConsoleControlConfig control_;
  size_t max_message_bytes_;
};

}  // namespace refloc
