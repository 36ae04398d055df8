#include "web_console/client_request.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace refloc {
namespace {

RequestVerdict refused(const char* reason) { return {std::nullopt, reason}; }

/// The number at key, when it is one, finite and within +-limit.
std::optional<double> bounded_number(const nlohmann::json& j, const char* key, double limit) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::nullopt;
  const double v = it->get<double>();
  if (!std::isfinite(v) || std::abs(v) > limit) return std::nullopt;
  return v;
}

}  // namespace

std::string command_result_frame(const RequestVerdict& verdict, const char* refusal) {
  // Refusal reasons and command names are fixed identifiers: nothing to escape.
  const char* reason = refusal != nullptr ? refusal : verdict.refusal;
  if (reason != nullptr || !verdict.command)
    return std::string(R"({"type":"command_result","ok":false,"reason":")") + (reason ? reason : "refused") +
           "\"}";
  const char* names[] = {"goal", "stop", "initial_pose"};
  return std::string(R"({"type":"command_result","ok":true,"command":")") +
         names[static_cast<int>(verdict.command->kind)] + "\"}";
}

bool RequestValidator::token_matches(const std::string& token) const {
  // Every character compared whatever the first difference: the time says nothing about the token.
  const std::string& expected = control_.token;
  unsigned difference = token.size() == expected.size() ? 0u : 1u;
  for (size_t i = 0; i < token.size(); ++i)
    difference |= static_cast<unsigned char>(token[i]) ^
                  static_cast<unsigned char>(expected.empty() ? 0 : expected[i % expected.size()]);
  return difference == 0 && !expected.empty();
}

RequestVerdict RequestValidator::judge(const std::string& message) const {
  if (message.size() > max_message_bytes_) return refused("too_large");
  const nlohmann::json j = nlohmann::json::parse(message, nullptr, false);
  if (j.is_discarded()) return refused("not_json");
  if (!j.is_object() || !j.contains("type") || !j["type"].is_string()) return refused("not_an_object");
  const std::string type = j["type"].get<std::string>();
  if (type != "goal" && type != "stop" && type != "initial_pose") return refused("unknown_type");
  if (!control_.enabled) return refused("control_disabled");
  const auto token = j.find("token");
  if (token == j.end() || !token->is_string() || !token_matches(token->get<std::string>()))
    return refused("bad_token");
  ConsoleCommand command;
  if (type == "stop") return {command, nullptr};
  const auto x = bounded_number(j, "x", kMaxGoalCoordinate_m);
  const auto y = bounded_number(j, "y", kMaxGoalCoordinate_m);
  const auto theta = bounded_number(j, "theta", 2.0 * M_PI);
  if (!x || !y || !theta) return refused("bad_number");
  command.kind = type == "goal" ? ConsoleCommand::Kind::kGoal : ConsoleCommand::Kind::kInitialPose;
  command.x = *x;
  command.y = *y;
  command.theta = *theta;
  return {command, nullptr};
}

}  // namespace refloc
