// What HEARTBEAT says while the driver refuses implausible scans: DEGRADED with the reason,
// back to OK once plausible scans flow for kRejectionHoldS; the log is rate-limited.

#include "lms100_driver/link_health.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

constexpr int64_t kS = 1000000;

TEST(LinkHealthRejection, RefusedScanMakesStreamingDegradedWithTheReason) {
  LinkHealth h(5.0, 0);
  h.on_state(SessionState::kStreaming, "streaming");
  h.on_scan_published(10 * kS, 100, true);
  h.on_scan_rejected(10 * kS + 20000, "DIST1 scale factor -1 (expected 1 or 2)");
  const LinkVerdict v = h.verdict(10 * kS + 40000);
  EXPECT_EQ(v.level, LinkLevel::kDegraded);
  EXPECT_EQ(v.detail, "refusing implausible scans: DIST1 scale factor -1 (expected 1 or 2)");
}

TEST(LinkHealthRejection, OkAgainOnceNoScanWasRefusedForTheHoldTime) {
  LinkHealth h(5.0, 0);
  h.on_state(SessionState::kStreaming, "streaming");
  h.on_scan_rejected(10 * kS, "x");
  h.on_scan_published(10 * kS + 500000, 100, true);
  EXPECT_EQ(h.verdict(10 * kS + 600000).level, LinkLevel::kDegraded);
  h.on_scan_published(11 * kS + 100000, 100, true);
  EXPECT_EQ(h.verdict(11 * kS + 100000).level, LinkLevel::kOk);
}

TEST(LinkHealthRejection, OnlyRefusedScansForErrorAfterIsAnErrorNamingBoth) {
  LinkHealth h(2.0, 0);
  h.on_state(SessionState::kStreaming, "streaming");
  for (int64_t t = 0; t <= 3 * kS; t += kS / 2) h.on_scan_rejected(t, "scan frequency 0.01 Hz");
  const LinkVerdict v = h.verdict(3 * kS);
  EXPECT_EQ(v.level, LinkLevel::kError);
  EXPECT_THAT(v.detail, HasSubstr("refusing implausible scans: scan frequency 0.01 Hz"));
  EXPECT_THAT(v.detail, HasSubstr("no scan for 3 s"));
}

TEST(LinkHealthRejection, LogLinesAreRateLimitedAndCountWhatWasSkipped) {
  LinkHealth h(5.0, 0);
  EXPECT_EQ(h.on_scan_rejected(1 * kS, "a"), "refused 1 implausible scan: a");
  int lines = 0;
  for (int i = 1; i <= 249; ++i) lines += !h.on_scan_rejected(1 * kS + i * 20000, "a").empty();  // 50 Hz, 5 s
  EXPECT_EQ(lines, 0);
  EXPECT_EQ(h.on_scan_rejected(6 * kS, "b"), "refused 250 implausible scans: b");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
