// A restarted matcher relocalizes globally before it tracks from the POSE prior.
#include "reflector_matcher/startup_relocalization.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 50'000'000;
constexpr int64_t kScan = 20'000;

TEST(StartupRelocalization, NoPriorUntilTheFirstGlobalOkThenTracking) {
  StartupRelocalization s(2.0);
  EXPECT_FALSE(s.prior_allowed(kT0));
  s.on_result(MatchStatus::kLost, MatchMode::kGlobal);
  EXPECT_FALSE(s.prior_allowed(kT0 + kScan));
  s.on_result(MatchStatus::kAmbiguous, MatchMode::kGlobal);
  EXPECT_FALSE(s.prior_allowed(kT0 + 2 * kScan));
  s.on_result(MatchStatus::kOk, MatchMode::kGlobal);
  EXPECT_TRUE(s.relocalized());
  EXPECT_FALSE(s.gave_up());
  EXPECT_TRUE(s.prior_allowed(kT0 + 3 * kScan));
}

TEST(StartupRelocalization, AnOkFromTrackingDoesNotCount) {
  StartupRelocalization s(2.0);
  EXPECT_FALSE(s.prior_allowed(kT0));
  s.on_result(MatchStatus::kOk, MatchMode::kTracking);  // cannot happen without a prior, and must not end it
  EXPECT_FALSE(s.relocalized());
  EXPECT_FALSE(s.prior_allowed(kT0 + kScan));
}

TEST(StartupRelocalization, AMapThatNeverRelocalizesGetsThePriorBackAfterTheWindow) {
  StartupRelocalization s(2.0);
  for (int64_t t = kT0; t <= kT0 + 2'000'000; t += kScan) {
    EXPECT_FALSE(s.prior_allowed(t)) << t - kT0;
    s.on_result(MatchStatus::kAmbiguous, MatchMode::kGlobal);
  }
  EXPECT_TRUE(s.prior_allowed(kT0 + 2'000'000 + kScan));
  EXPECT_TRUE(s.gave_up());
  EXPECT_FALSE(s.relocalized());
}

TEST(StartupRelocalization, ZeroWindowTracksFromTheFirstScan) {
  StartupRelocalization s(0.0);
  EXPECT_TRUE(s.prior_allowed(kT0));
  EXPECT_TRUE(s.done());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
