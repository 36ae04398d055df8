// refloc-survey static: association across scans, the autocorrelation time, the range bias
// along the line of sight, and 100 rendered scans of the demo hall from one pose: every
// surveyed reflector within 3 sigma of the truth, sigma reported.

#include "static_survey.hpp"
#include "rendered_static_survey.hpp"
#include "static_progress.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using testing::rendered_static_survey;
using testing::RenderedSurvey;

ReflectorDetection detection_at(double x, double y) {
  ReflectorDetection d;
  d.laser_p_center = {x, y};
  d.covariance = Eigen::Matrix2d::Identity() * 1e-6;
  return d;
}

TEST(StaticSurvey, AutocorrelationTimeIsOneForWhiteNoiseAndLargeForDrift) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> white, drifting;
  double ar = 0.0;
  for (int i = 0; i < 20000; ++i) {
    white.push_back(noise(rng));
    ar = 0.9 * ar + noise(rng);
    drifting.push_back(ar);
  }
  EXPECT_NEAR(integrated_autocorrelation_time(white), 1.0, 0.1);
  // AR(1) with phi 0.9: tau = (1 + phi) / (1 - phi) = 19.
  EXPECT_NEAR(integrated_autocorrelation_time(drifting), 19.0, 6.0);  // estimator sd ~2.6
}

TEST(StaticSurvey, AssociatesByPositionAndDropsRarelySeenTracks) {
  StaticSurveyConfig config;
  config.range_bias_sigma_m = 0.0;
  StaticSurvey survey(config);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.002);
  for (int i = 0; i < 10; ++i) {
    std::vector<ReflectorDetection> scan{detection_at(5.0 + noise(rng), 1.0 + noise(rng)),
                                         detection_at(5.0 + noise(rng), 1.15 + noise(rng)),
                                         detection_at(3.0 + noise(rng), -2.0 + noise(rng))};
    if (i == 4) scan.push_back(detection_at(8.0, 0.0));  // a glint, once
    if (i >= 8) scan.pop_back();                         // the third one missed twice: 80 %
    survey.add_scan(scan);
  }
  const StaticSurveyResult result = survey.finish(Pose2{1.0, 2.0, M_PI / 2});
  EXPECT_EQ(result.scans, 10);
  ASSERT_EQ(result.reflectors.size(), 3u);
  ASSERT_EQ(result.dropped_times_seen, std::vector<int>{1});
  // In order of bearing: (3, -2), then (5, 1), then (5, 1.15); ids 1, 2, 3.
  EXPECT_EQ(result.reflectors[0].times_seen, 8);
  EXPECT_NEAR(result.reflectors[1].laser_p_center.y(), 1.0, 0.003);
  EXPECT_NEAR(result.reflectors[2].laser_p_center.y(), 1.15, 0.003);
  EXPECT_EQ(result.reflectors[2].id, 3);
  // map = (1, 2) + rot(90 deg) * laser: (5, 1) -> (0, 7).
  EXPECT_NEAR(result.reflectors[1].map_p_center.x(), 0.0, 0.003);
  EXPECT_NEAR(result.reflectors[1].map_p_center.y(), 7.0, 0.003);
}

TEST(StaticSurvey, StatedRangeBiasMovesCentresAlongTheLineOfSight) {
  StaticSurveyConfig config;
  config.range_bias_m = 0.03;
  config.range_bias_sigma_m = 0.01;
  config.scan_bias_fraction = 0.0;
  StaticSurvey survey(config);
  for (int i = 0; i < 5; ++i) survey.add_scan({detection_at(3.0, 4.0)});  // range 5
  survey.add_scan({detection_at(3.0, 4.0), detection_at(-1.0, 0.0)});
  config.min_seen_fraction = 0.5;
  const StaticSurveyResult result = survey.finish(Pose2{});
  ASSERT_EQ(result.reflectors.size(), 1u);
  const StaticSurveyReflector& r = result.reflectors[0];
  EXPECT_NEAR(r.laser_p_center.x(), 3.0 - 0.03 * 0.6, 1e-12);
  EXPECT_NEAR(r.laser_p_center.y(), 4.0 - 0.03 * 0.8, 1e-12);
  // Identical detections: no scatter; the covariance is the bias sigma along (0.6, 0.8).
  EXPECT_NEAR(r.map_cov_center(0, 0), 1e-4 * 0.36, 1e-12);
  EXPECT_NEAR(r.map_cov_center(0, 1), 1e-4 * 0.48, 1e-12);
  EXPECT_NEAR(r.map_cov_center(1, 1), 1e-4 * 0.64, 1e-12);
}

std::string progress_text(bool terminal, int total, int updates) {
  std::FILE* file = std::tmpfile();
  SurveyProgress progress(file, total, terminal);
  for (int done = 1; done <= updates; ++done) progress.update(done, 5);
  progress.finish();
  std::rewind(file);
  std::string text;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += static_cast<char>(c);
  std::fclose(file);
  return text;
}

TEST(StaticSurvey, ProgressIsALineEveryTenPercentUnlessATerminal) {
  const std::string lines = progress_text(false, 100, 100);
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 11);  // 0 %, 10 %, ..., 100 %
  EXPECT_THAT(lines, ::testing::HasSubstr("scans  50 % (50/100), 5 reflectors in the last\n"));
  EXPECT_EQ(lines.find('\r'), std::string::npos);
  const std::string bar = progress_text(true, 20, 10);
  EXPECT_EQ(std::count(bar.begin(), bar.end(), '\r'), 10);
  EXPECT_EQ(std::count(bar.begin(), bar.end(), '\n'), 1);  // the bar's line ends once
  EXPECT_THAT(bar, ::testing::HasSubstr("\rscans [###############...............]  50 % 10/20"));
}

void print_run(const char* what, const RenderedSurvey& run) {
  std::printf("%s: %d entries (%d reflectors, %d at tape or metal) of %d reflectors in view\n", what,
              static_cast<int>(run.comparison.size()), run.reflectors(),
              static_cast<int>(run.comparison.size()) - run.reflectors(), run.visible);
  for (const auto& c : run.comparison) {
    std::printf("  id %2d (true %2d%s): error %6.2f mm, sigma %5.2f mm, %5.2f sigma\n", c.id, c.true_id,
                c.at_distractor ? ", a distractor" : "", 1e3 * c.error.norm(), 1e3 * c.major_sigma_m,
                c.mahalanobis);
  }
  std::printf("  reflectors inside 3 sigma: %d of %d\n", run.inside_three_sigma(), run.reflectors());
}

constexpr int kScans = 100;
const Pose2 kPose{2.0, 2.0, 1.5};  // the west end, facing north: 6 reflectors detected, no tape

TEST(StaticSurveyRendered, HundredScansFromOnePoseEveryReflectorWithinThreeSigma) {
  StaticSurveyConfig config;
  config.range_bias_sigma_m = 0.0;  // the rendered sensor has no systematic range error: stated as known
  const RenderedSurvey run = rendered_static_survey(kPose, {}, config, kScans, 14);
  print_run("demo hall, 100 scans", run);
  EXPECT_GE(run.reflectors(), 5);
  EXPECT_EQ(run.reflectors(), static_cast<int>(run.comparison.size()));
  EXPECT_EQ(run.inside_three_sigma(), run.reflectors());
  for (const auto& c : run.comparison) {
    EXPECT_LT(c.error.norm(), 0.01) << "id " << c.id;
    EXPECT_LT(c.major_sigma_m, 0.006) << "id " << c.id;
  }
}

TEST(StaticSurveyRendered, RangeOffsetIsRemovedWhenStatedAndCoveredByTheDefaultSigma) {
  sim::Lms100ErrorModel biased;
  biased.range_offset =
      0.03;  // the LMS100's typical systematic error, as robot_sim's render/sensor/range_offset
  StaticSurveyConfig unaware;  // the user states nothing: 0 +- 30 mm
  StaticSurveyConfig stated;
  stated.range_bias_m = 0.03;
  stated.range_bias_sigma_m = 0.002;
  StaticSurveyConfig wrong;  // the user claims a perfect sensor
  wrong.range_bias_sigma_m = 0.0;
  const RenderedSurvey default_sigma = rendered_static_survey(kPose, biased, unaware, kScans, 15);
  const RenderedSurvey corrected = rendered_static_survey(kPose, biased, stated, kScans, 15);
  const RenderedSurvey overconfident = rendered_static_survey(kPose, biased, wrong, kScans, 15);
  print_run("offset +30 mm, bias not stated (0 +- 30 mm)", default_sigma);
  print_run("offset +30 mm, --range-bias-mm 30 --range-bias-sigma-mm 2", corrected);
  print_run("offset +30 mm, --range-bias-mm 0 --range-bias-sigma-mm 0", overconfident);
  ASSERT_GE(corrected.reflectors(), 5);
  EXPECT_EQ(default_sigma.inside_three_sigma(), default_sigma.reflectors());
  EXPECT_EQ(corrected.inside_three_sigma(), corrected.reflectors());
  EXPECT_EQ(overconfident.inside_three_sigma(), 0);  // 30 mm out along every line of sight
  for (const auto& c : corrected.comparison) EXPECT_LT(c.error.norm(), 0.01) << "id " << c.id;
  for (const auto& c : default_sigma.comparison) EXPECT_GT(c.error.norm(), 0.02) << "id " << c.id;
}

// The floor (scan_bias_fraction) measured: 25 random poses of the demo hall, 100 scans each, the
// share of reflectors within 3 sigma without a floor and with the default. A study, not a check:
// build/bin/tools_refloc_survey_static_tests --gtest_also_run_disabled_tests --gtest_filter='*Study*'
TEST(StaticSurveyRendered, DISABLED_StudyOfTheFloorOverRandomPoses) {
  const sim::World world = sim::load_world(testing::kConfigDir + "world_demo.json");
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Pose2> poses;
  while (poses.size() < 25) {
    const auto& a = world.drivable_areas[rng() % world.drivable_areas.size()];
    const Pose2 p{a.x_min + unit(rng) * (a.x_max - a.x_min), a.y_min + unit(rng) * (a.y_max - a.y_min),
                  (2.0 * unit(rng) - 1.0) * M_PI};
    if (sim::clearance(world, p.translation()) > 0.5) poses.push_back(p);
  }
  for (const double fraction : {0.0, 0.1, 0.2, 0.25, 0.3, 0.5}) {
    StaticSurveyConfig config;
    config.range_bias_sigma_m = 0.0;
    config.scan_bias_fraction = fraction;
    int inside = 0, reflectors = 0, distractors = 0;
    double worst = 0.0, sigma_sum = 0.0;
    for (size_t k = 0; k < poses.size(); ++k) {
      const RenderedSurvey run = rendered_static_survey(poses[k], {}, config, kScans, 100 + k);
      inside += run.inside_three_sigma();
      reflectors += run.reflectors();
      distractors += static_cast<int>(run.comparison.size()) - run.reflectors();
      for (const auto& c : run.comparison) {
        if (c.at_distractor) continue;
        worst = std::max(worst, c.mahalanobis);
        sigma_sum += c.major_sigma_m;
      }
    }
    std::printf(
        "scan_bias_fraction %.2f: %d of %d reflectors inside 3 sigma (%.3f), worst %.2f sigma, mean sigma "
        "%.2f mm; %d distractors mapped\n",
        fraction, inside, reflectors, static_cast<double>(inside) / reflectors, worst,
        1e3 * sigma_sum / reflectors, distractors);
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
