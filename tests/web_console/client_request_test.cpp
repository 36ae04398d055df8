// RequestValidator (every refusal by reason) and the Origin rule.

#include "web_console/client_request.hpp"
#include "web_console/origin_rule.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

RequestValidator validator(bool enabled) {
  ConsoleControlConfig control;
  control.enabled = enabled;
  control.token = "s3cret-token";
  return RequestValidator(control, 256);
}

std::string refusal(const RequestValidator& v, const std::string& message) {
  const RequestVerdict verdict = v.judge(message);
  return verdict.refusal ? verdict.refusal : "accepted";
}

TEST(RequestValidator, AGoalWithTheTokenIsAcceptedWithItsCoordinates) {
  const RequestVerdict verdict =
      validator(true).judge(R"({"type":"goal","token":"s3cret-token","x":1.5,"y":-2.25,"theta":0.5})");
  ASSERT_TRUE(verdict.command);
  EXPECT_EQ(verdict.command->kind, ConsoleCommand::Kind::kGoal);
  EXPECT_DOUBLE_EQ(verdict.command->x, 1.5);
  EXPECT_DOUBLE_EQ(verdict.command->y, -2.25);
  EXPECT_DOUBLE_EQ(verdict.command->theta, 0.5);
  const RequestVerdict stop = validator(true).judge(R"({"type":"stop","token":"s3cret-token"})");
  ASSERT_TRUE(stop.command);
  EXPECT_EQ(stop.command->kind, ConsoleCommand::Kind::kStop);
}

TEST(RequestValidator, AnInitialPoseIsACommandLikeAGoalWithTheSameChecks) {
  const RequestVerdict verdict = validator(true).judge(
      R"({"type":"initial_pose","token":"s3cret-token","x":12.0,"y":7.0,"theta":-1.0})");
  ASSERT_TRUE(verdict.command);
  EXPECT_EQ(verdict.command->kind, ConsoleCommand::Kind::kInitialPose);
  EXPECT_DOUBLE_EQ(verdict.command->x, 12.0);
  EXPECT_DOUBLE_EQ(verdict.command->theta, -1.0);
  EXPECT_EQ(refusal(validator(true), R"({"type":"initial_pose","x":1,"y":2,"theta":0})"), "bad_token");
  EXPECT_EQ(
      refusal(validator(false), R"({"type":"initial_pose","token":"s3cret-token","x":1,"y":2,"theta":0})"),
      "control_disabled");
  EXPECT_EQ(refusal(validator(true), R"({"type":"initial_pose","token":"s3cret-token","x":1,"y":2})"),
            "bad_number");
}

TEST(RequestValidator, TheSenderIsToldWhatBecameOfItsCommand) {
  const RequestValidator on = validator(true);
  EXPECT_EQ(command_result_frame(on.judge(R"({"type":"goal","token":"s3cret-token","x":1,"y":2,"theta":0})")),
            R"({"type":"command_result","ok":true,"command":"goal"})");
  EXPECT_EQ(command_result_frame(on.judge(R"({"type":"initial_pose","x":1,"y":2,"theta":0})")),
            R"({"type":"command_result","ok":false,"reason":"bad_token"})");
  EXPECT_EQ(command_result_frame(on.judge(R"({"type":"stop","token":"s3cret-token"})"), "inbox_full"),
            R"({"type":"command_result","ok":false,"reason":"inbox_full"})");
}

TEST(RequestValidator, EveryBadMessageIsRefusedWithItsReason) {
  const RequestValidator on = validator(true);
  EXPECT_EQ(refusal(on, std::string(257, ' ')), "too_large");
  EXPECT_EQ(refusal(on, "{\"type\": \"goal\""), "not_json");
  EXPECT_EQ(refusal(on, "[1, 2]"), "not_an_object");
  EXPECT_EQ(refusal(on, R"({"type": 3})"), "not_an_object");
  EXPECT_EQ(refusal(on, R"({"type": "reboot", "token": "s3cret-token"})"), "unknown_type");
  EXPECT_EQ(refusal(on, R"({"type": "stop"})"), "bad_token");
  EXPECT_EQ(refusal(on, R"({"type": "stop", "token": "s3cret-tokem"})"), "bad_token");
  EXPECT_EQ(refusal(on, R"({"type": "stop", "token": "s3cret-token-and-more"})"), "bad_token");
  EXPECT_EQ(refusal(on, R"({"type": "goal", "token": "s3cret-token", "x": 1, "y": 2})"), "bad_number");
  EXPECT_EQ(refusal(on, R"({"type": "goal", "token": "s3cret-token", "x": "1", "y": 2, "theta": 0})"),
            "bad_number");
  EXPECT_EQ(refusal(on, R"({"type": "goal", "token": "s3cret-token", "x": 1e300, "y": 2, "theta": 0})"),
            "bad_number");
  EXPECT_EQ(refusal(on, R"({"type": "goal", "token": "s3cret-token", "x": 1, "y": 2, "theta": 7})"),
            "bad_number");
  EXPECT_EQ(refusal(validator(false), R"({"type": "stop", "token": "s3cret-token"})"), "control_disabled");
}

TEST(RequestValidator, AnEmptyTokenNeverMatches) {
  ConsoleControlConfig control;
  control.enabled = true;
  const RequestValidator v(control, 256);
  EXPECT_EQ(refusal(v, R"({"type": "stop", "token": ""})"), "bad_token");
}

TEST(OriginRule, ThePagesOwnHostAListedOriginOrNoOriginAreAccepted) {
  const std::vector<std::string> allowed = {"http://robot.local:8080"};
  EXPECT_EQ(judge_origin("http://127.0.0.1:8080", "127.0.0.1:8080", {}), OriginVerdict::kAccepted);
  EXPECT_EQ(judge_origin("HTTP://Robot:8080/", "robot:8080", {}), OriginVerdict::kAccepted);
  EXPECT_EQ(judge_origin("http://robot.local:8080", "10.0.0.5:8080", allowed), OriginVerdict::kAccepted);
  EXPECT_EQ(judge_origin("", "127.0.0.1:8080", {}), OriginVerdict::kAccepted);
}

TEST(OriginRule, AnotherSiteAnotherPortOrNullIsRefused) {
  EXPECT_EQ(judge_origin("http://evil.example", "127.0.0.1:8080", {}), OriginVerdict::kRefused);
  EXPECT_EQ(judge_origin("http://127.0.0.1:9999", "127.0.0.1:8080", {}), OriginVerdict::kRefused);
  EXPECT_EQ(judge_origin("null", "127.0.0.1:8080", {}), OriginVerdict::kRefused);
  EXPECT_EQ(judge_origin("http://127.0.0.1:8080", "", {}), OriginVerdict::kRefused);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
